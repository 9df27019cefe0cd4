/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.compiler;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.rei.vepl.VeplStandaloneSetup;
import org.rei.vepl.validation.KnownQueries;
import org.rei.vepl.vepl.PatternFile;

import com.google.inject.Injector;

/**
 * Parses, validates and compiles a set of .vepl files together (they may refer to each other's events and
 * signals). Any error stops it with every message as {@code file:line:column: message}.
 */
public final class VeplLoader {

	/** A .vepl file: its file name (the consumption scope and the name of its .drl) and its text. */
	public record Source(String name, String text) {
	}

	/** The pattern files do not validate. */
	public static final class VeplException extends Exception {
		private static final long serialVersionUID = 1L;

		public VeplException(String message) {
			super(message);
		}
	}

	private static Injector injector;

	private VeplLoader() {
	}

	private static synchronized Injector injector() {
		if (injector == null) {
			injector = VeplStandaloneSetup.doSetup();
		}
		return injector;
	}

	/** Every *.vepl of a folder, sorted by file name so builds repeat. */
	public static List<Source> folder(Path dir) throws IOException {
		if (!Files.isDirectory(dir)) {
			throw new IOException("not a folder of .vepl files: " + dir);
		}
		List<Source> out = new ArrayList<>();
		try (Stream<Path> files = Files.list(dir)) {
			for (Path p : files.filter(f -> f.getFileName().toString().endsWith(".vepl"))
					.sorted(Comparator.comparing(f -> f.getFileName().toString())).toList()) {
				out.add(new Source(p.toString(), Files.readString(p, StandardCharsets.UTF_8)));
			}
		}
		return out;
	}

	/**
	 * Parses and validates; {@code knownQueries} are the DRL queries the rules will run with. Every check is the
	 * validator's, as the language server runs it ({@link org.rei.vepl.validation.VeplResourceValidator}), and every
	 * file is checked: the message lists the errors of all of them.
	 */
	public static List<VeplCompiler.Unit> load(List<Source> sources, Set<String> knownQueries) throws VeplException {
		XtextResourceSet set = injector().getInstance(XtextResourceSet.class);
		KnownQueries.attach(set, knownQueries);
		List<VeplCompiler.Unit> units = new ArrayList<>();
		for (int i = 0; i < sources.size(); i++) {
			Source s = sources.get(i);
			// one URI per source: a user's geometry.vepl beside the packaged one is another resource
			Resource r = set.createResource(URI.createURI("vepl:/" + i + "/" + VeplCompiler.baseName(s.name()) + ".vepl"));
			try {
				r.load(new ByteArrayInputStream(s.text().getBytes(StandardCharsets.UTF_8)), null);
			} catch (IOException e) {
				throw new UncheckedIOException(e);
			}
			units.add(new VeplCompiler.Unit(s.name(), (PatternFile) (r.getContents().isEmpty() ? null
					: r.getContents().get(0))));
		}
		EcoreUtil.resolveAll(set);
		IResourceValidator validator = injector().getInstance(IResourceValidator.class);
		List<String> errors = new ArrayList<>();
		for (int i = 0; i < units.size(); i++) {
			XtextResource r = (XtextResource) set.getResources().get(i);
			for (Issue issue : validator.validate(r, CheckMode.ALL, CancelIndicator.NullImpl)) {
				if (issue.getSeverity() == Severity.ERROR) {
					errors.add(sources.get(i).name() + ":" + issue.getLineNumber() + ":" + issue.getColumn() + ": "
							+ issue.getMessage() + " [" + issue.getCode() + "]");
				}
			}
		}
		if (!errors.isEmpty()) {
			throw new VeplException("pattern files do not validate:\n  " + String.join("\n  ", errors));
		}
		return units;
	}

	/** Loads and compiles in one go. */
	public static CompiledRules compile(List<Source> sources, Set<String> knownQueries, DrlTarget target)
			throws VeplException {
		return VeplCompiler.compile(load(sources, knownQueries), target);
	}
}
