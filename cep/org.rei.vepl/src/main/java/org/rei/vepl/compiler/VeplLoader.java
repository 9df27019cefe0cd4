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
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.rei.vepl.VeplStandaloneSetup;
import org.rei.vepl.validation.KnownQueries;
import org.rei.vepl.validation.VeplIssueCodes;
import org.rei.vepl.vepl.Element;
import org.rei.vepl.vepl.Event;
import org.rei.vepl.vepl.PatternFile;
import org.rei.vepl.vepl.Rule;
import org.rei.vepl.vepl.Signal;

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

	/** Parses and validates; {@code knownQueries} are the DRL queries the rules will run with. */
	public static List<VeplCompiler.Unit> load(List<Source> sources, Set<String> knownQueries) throws VeplException {
		XtextResourceSet set = injector().getInstance(XtextResourceSet.class);
		KnownQueries.attach(set, knownQueries);
		List<String> tooDeep = new ArrayList<>();
		for (Source s : sources) {
			String where = tooDeep(s.text());
			if (where != null) {
				tooDeep.add(s.name() + ":" + where);
			}
		}
		if (!tooDeep.isEmpty()) { // the parser recurses per bracket: it would overflow the stack, not report
			throw new VeplException("pattern files do not validate:\n  " + String.join("\n  ", tooDeep));
		}
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
			if (units.get(i).model() == null) { // nothing but whitespace and comments: no root to validate
				errors.add(sources.get(i).name() + ":1:1: The file declares no event, signal or rule [" +
						VeplIssueCodes.EMPTY_FILE + "]");
				continue;
			}
			XtextResource r = (XtextResource) set.getResources().get(i);
			for (Issue issue : validator.validate(r, CheckMode.ALL, CancelIndicator.NullImpl)) {
				if (issue.getSeverity() == Severity.ERROR) {
					errors.add(sources.get(i).name() + ":" + issue.getLineNumber() + ":" + issue.getColumn() + ": "
							+ issue.getMessage() + " [" + issue.getCode() + "]");
				}
			}
		}
		if (errors.isEmpty()) { // names are only compared once every file parsed and validated
			errors.addAll(crossFileDuplicates(units));
		}
		if (!errors.isEmpty()) {
			throw new VeplException("pattern files do not validate:\n  " + String.join("\n  ", errors));
		}
		return units;
	}

	/** Brackets nested deeper than any pattern needs; the parser recurses once per level. */
	public static final int MAX_NESTING = 100;

	/** "line:column: message [code]" of the first bracket beyond {@link #MAX_NESTING}, or null. */
	static String tooDeep(String text) {
		int depth = 0;
		int line = 1;
		int column = 0;
		for (int i = 0; i < text.length(); i++) {
			char c = text.charAt(i);
			column++;
			if (c == '\n') {
				line++;
				column = 0;
			} else if (c == '/' && i + 1 < text.length() && text.charAt(i + 1) == '/') {
				while (i + 1 < text.length() && text.charAt(i + 1) != '\n') {
					i++;
				}
			} else if (c == '"') { // a rule's name; an unterminated one ends at the line's end
				while (i + 1 < text.length() && text.charAt(i + 1) != '"' && text.charAt(i + 1) != '\n') {
					i++;
					column++;
				}
			} else if (c == '(' || c == '{' || c == '[') {
				if (++depth > MAX_NESTING) {
					return line + ":" + column + ": brackets nested deeper than " + MAX_NESTING + " levels ["
							+ VeplIssueCodes.TOO_DEEP + "]";
				}
			} else if ((c == ')' || c == '}' || c == ']') && depth > 0) {
				depth--;
			}
		}
		return null;
	}

	/** Names of events, signals and rules are global across the loaded files. */
	private static List<String> crossFileDuplicates(List<VeplCompiler.Unit> units) {
		List<String> errors = new ArrayList<>();
		Map<String, String> seen = new HashMap<>();
		for (VeplCompiler.Unit u : units) {
			Map<String, String> own = new HashMap<>();
			for (Element e : u.model().getElements()) {
				String key = e instanceof Event ev ? "event " + ev.getName()
						: e instanceof Signal s ? "signal " + s.getName() : "rule \"" + ((Rule) e).getName() + "\"";
				String where = u.name() + ":" + NodeModelUtils.getNode(e).getStartLine();
				String before = seen.get(key);
				if (before != null) {
					errors.add(where + ": " + key + " is also declared at " + before);
				}
				own.putIfAbsent(key, where);
			}
			own.forEach(seen::putIfAbsent);
		}
		return errors;
	}

	/** Loads and compiles in one go. */
	public static CompiledRules compile(List<Source> sources, Set<String> knownQueries, DrlTarget target)
			throws VeplException {
		return VeplCompiler.compile(load(sources, knownQueries), target);
	}
}
