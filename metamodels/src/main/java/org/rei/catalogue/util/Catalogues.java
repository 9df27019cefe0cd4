/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.catalogue.util;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URL;
import java.util.Optional;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceFactoryImpl;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.CataloguePackage;
import org.rei.catalogue.ObjectType;

/** Loads catalogues: the default one shipped in this jar, or a user's file. */
public final class Catalogues {

	/** File extension of catalogue files (XMI). */
	public static final String EXTENSION = "catalogue";

	/** Classpath location of the default catalogue. */
	public static final String DEFAULT_LOCATION = "/org/rei/catalogue/default.catalogue";

	private Catalogues() {
	}

	/** Makes {@code *.catalogue} loadable in the given resource set. */
	public static void register(ResourceSet resourceSet) {
		CataloguePackage.eINSTANCE.eClass();
		resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap()
				.putIfAbsent(EXTENSION, new XMIResourceFactoryImpl());
	}

	/** URI of the default catalogue inside this jar (or classes folder). */
	public static URI defaultUri() {
		URL url = Catalogues.class.getResource(DEFAULT_LOCATION);
		if (url == null) {
			throw new IllegalStateException("default catalogue missing from the classpath: " + DEFAULT_LOCATION);
		}
		return URI.createURI(url.toString());
	}

	/** Loads (or returns the already loaded) default catalogue in the given resource set. */
	public static Catalogue loadDefault(ResourceSet resourceSet) {
		return load(resourceSet, defaultUri());
	}

	/** Loads a catalogue file. */
	public static Catalogue load(ResourceSet resourceSet, URI uri) {
		register(resourceSet);
		Resource resource = resourceSet.getResource(uri, true);
		if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof Catalogue catalogue)) {
			throw new UncheckedIOException(new IOException("not a catalogue: " + uri));
		}
		return catalogue;
	}

	/** The type with the given name, if the catalogue has one. */
	public static Optional<ObjectType> find(Catalogue catalogue, String name) {
		return catalogue.getOwnedTypes().stream().filter(t -> name.equals(t.getName())).findFirst();
	}
}
