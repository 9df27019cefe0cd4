/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.tests;

import java.nio.file.Path;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.rei.context.TestCase;

import com.google.inject.Inject;
import com.google.inject.Provider;

/** Loads .rei files from disk the way the command line does, so positions are those a user sees. */
public class ReiFiles {

	@Inject
	private Provider<XtextResourceSet> resourceSets;

	@Inject
	private IResourceValidator validator;

	public XtextResource load(Path file) {
		return (XtextResource) resourceSets.get().getResource(URI.createFileURI(file.toAbsolutePath().toString()), true);
	}

	public TestCase testCase(Path file) {
		return (TestCase) load(file).getContents().get(0);
	}

	public List<Issue> validate(Path file) {
		return validator.validate(load(file), CheckMode.ALL, CancelIndicator.NullImpl);
	}

	/** Repository root, found from the module's working directory. */
	public static Path repository() {
		Path dir = Path.of("").toAbsolutePath();
		while (dir != null && !dir.resolve("examples").toFile().isDirectory()) {
			dir = dir.getParent();
		}
		if (dir == null) {
			throw new IllegalStateException("examples/ not found above " + Path.of("").toAbsolutePath());
		}
		return dir;
	}
}
