/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.catalogue;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.TestCase;

/**
 * The user catalogues a test case imports ({@code import "furniture.rei"}), loaded into the test case's resource
 * set: the scope offers their types, the validator reports why one could not be used. Paths are relative to the
 * importing file, as a user reads them.
 */
public final class CatalogueImports {

	/** One import: the catalogue it names, or why there is none (then {@code catalogue} is null). */
	public record Import(int index, String path, Catalogue catalogue, Resource resource, String problem) {
	}

	private CatalogueImports() {
	}

	/** Every import of the test case in order, each loaded (or found wanting). */
	public static List<Import> of(TestCase testCase) {
		Resource importer = testCase.eResource();
		List<Import> result = new ArrayList<>();
		List<String> paths = testCase.getCatalogueImports();
		for (int i = 0; i < paths.size(); i++) {
			result.add(load(importer, i, paths.get(i)));
		}
		return result;
	}

	/** The imported catalogues that loaded, in import order. */
	public static List<Catalogue> catalogues(TestCase testCase) {
		return of(testCase).stream().map(Import::catalogue).filter(c -> c != null).toList();
	}

	private static Import load(Resource importer, int index, String path) {
		if (path == null || path.isBlank()) {
			return new Import(index, path, null, null, "The import names no file: expected a catalogue's path");
		}
		URI uri;
		try {
			uri = URI.createFileURI(path).resolve(importer == null ? URI.createFileURI("") : importer.getURI());
		} catch (IllegalArgumentException e) {
			return new Import(index, path, null, null, "Cannot read catalogue '" + path + "': " + e.getMessage());
		}
		if (importer != null && uri.equals(importer.getURI())) {
			return new Import(index, path, null, null, "A test case can not import itself");
		}
		ResourceSet resourceSet = importer == null ? null : importer.getResourceSet();
		if (resourceSet == null || !resourceSet.getURIConverter().exists(uri, null)) {
			return new Import(index, path, null, null,
					"Cannot read catalogue '" + path + "': no such file (paths are relative to this test case)");
		}
		Resource resource;
		try {
			Catalogues.register(resourceSet);
			resource = resourceSet.getResource(uri, true);
		} catch (RuntimeException e) {
			Resource broken = resourceSet.getResource(uri, false);
			if (broken != null && !broken.getContents().isEmpty()) {
				resource = broken; // parsed with errors: the validator reports them
			} else {
				return new Import(index, path, null, null, "Cannot read catalogue '" + path + "': "
						+ (e.getCause() != null ? e.getCause().getMessage() : e.getMessage()));
			}
		}
		EObject root = resource.getContents().isEmpty() ? null : resource.getContents().get(0);
		if (root instanceof Catalogue catalogue) {
			return new Import(index, path, catalogue, resource, null);
		}
		String what = root instanceof TestCase ? "a test case" : root == null ? "empty" : "not a catalogue";
		return new Import(index, path, null, resource, "'" + path + "' is " + what
				+ ": expected a catalogue file ('catalogue NAME { type ... }')");
	}
}
