/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.model;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.xmi.XMLResource;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceImpl;
import org.rei.catalogue.CataloguePackage;
import org.rei.context.ContextPackage;
import org.rei.runtime.RuntimePackage;
import org.rei.runtime.RuntimeModel;

/** The runtime model as XMI (the {@code snapshot} RPC, and the file written on exit), and back. */
public final class Snapshots {

	private static final Map<Object, Object> OPTIONS = Map.of(XMLResource.OPTION_ENCODING, "UTF-8");

	static {
		// standalone EMF: the packages register themselves in the global registry on first access
		RuntimePackage.eINSTANCE.eClass();
		ContextPackage.eINSTANCE.eClass();
		CataloguePackage.eINSTANCE.eClass();
	}

	private Snapshots() {
	}

	/** The XMI text of a resource (the runtime model and the run's catalogue). */
	public static String toXmi(Resource resource) {
		ByteArrayOutputStream out = new ByteArrayOutputStream();
		try {
			resource.save(out, OPTIONS);
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
		return out.toString(StandardCharsets.UTF_8);
	}

	public static void save(Resource resource, Path file) throws IOException {
		Files.writeString(file, toXmi(resource), StandardCharsets.UTF_8);
	}

	/** Loads a snapshot back into EMF; the first root is the runtime model. */
	public static RuntimeModel load(String xmi) {
		Resource r = new XMIResourceImpl(URI.createURI("snapshot.xmi"));
		try {
			r.load(new ByteArrayInputStream(xmi.getBytes(StandardCharsets.UTF_8)), OPTIONS);
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
		if (r.getContents().isEmpty() || !(r.getContents().get(0) instanceof RuntimeModel model)) {
			throw new IllegalArgumentException("not a runtime model snapshot");
		}
		return model;
	}
}
