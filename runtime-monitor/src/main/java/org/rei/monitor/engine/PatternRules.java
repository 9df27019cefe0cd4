/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.rei.vepl.compiler.CompiledRules;
import org.rei.vepl.compiler.DrlTarget;
import org.rei.vepl.compiler.VeplLoader;
import org.rei.vepl.validation.KnownQueries;

/**
 * The transition rules as VEPL patterns (docs/vepl.md): the packaged copies of {@code cep/patterns/} and/or the
 * {@code *.vepl} of a folder, compiled to DRL at start against the queries the session will run. The Maven build
 * compiles the packaged patterns ahead of time into {@link DrlSources#RULES}; a test checks both give the same DRL.
 */
public final class PatternRules {

	/** Classpath folder of the packaged patterns (a copy of the repository's {@code cep/patterns/}). */
	public static final String PATTERNS = "/org/rei/monitor/patterns";

	private PatternRules() {
	}

	/** The packaged default patterns. */
	public static List<VeplLoader.Source> packaged() {
		try {
			return VeplLoader.folder(DrlSources.packagedFolder(PATTERNS, "patterns"));
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}

	/** The packaged defaults (unless {@code withDefaults} is false) followed by the patterns of {@code dir}. */
	public static List<VeplLoader.Source> select(boolean withDefaults, Path dir) throws IOException {
		List<VeplLoader.Source> out = new ArrayList<>(withDefaults ? packaged() : List.of());
		if (dir != null) {
			List<VeplLoader.Source> own = VeplLoader.folder(dir);
			if (own.isEmpty()) {
				throw new IOException("no .vepl files in " + dir);
			}
			out.addAll(own);
		}
		if (out.isEmpty()) {
			throw new IOException("no patterns: give --patterns DIR or keep the default patterns");
		}
		return out;
	}

	/**
	 * Compiles patterns to DRL for the monitor's classes; a pattern error fails with file, line and column.
	 *
	 * @param queries the query files the session is built with (queryEvents must name one of their queries)
	 */
	public static List<DrlSources.Source> compile(List<VeplLoader.Source> patterns, List<DrlSources.Source> queries)
			throws VeplLoader.VeplException {
		return compileWithUtilities(patterns, queries).drl();
	}

	/**
	 * The DRL of {@link #compile} and the utility every loaded pattern declares for its signals.
	 *
	 * @param drl         the generated rule files
	 * @param utilities   signal -> declared utility, in declaration order; null for a signal declared without one
	 * @param transitions signal -> the zone change it declares ({@code transition geometry FAR -> CLOSE})
	 */
	public record Compiled(List<DrlSources.Source> drl, Map<String, Double> utilities,
			Map<String, CompiledRules.Transition> transitions) {
	}

	/** As {@link #compile}, keeping the declared utilities (the evaluator scores signals with them). */
	public static Compiled compileWithUtilities(List<VeplLoader.Source> patterns, List<DrlSources.Source> queries)
			throws VeplLoader.VeplException {
		Set<String> known = new TreeSet<>();
		for (DrlSources.Source q : queries) {
			known.addAll(KnownQueries.inDrl(q.text()));
		}
		CompiledRules compiled = VeplLoader.compile(patterns, known, DrlTarget.MONITOR);
		List<DrlSources.Source> out = new ArrayList<>();
		for (CompiledRules.DrlFile f : compiled.files()) {
			out.add(new DrlSources.Source("patterns/" + f.name(), f.text()));
		}
		// a copy that keeps the order and the nulls (Map.copyOf would reject the nulls)
		return new Compiled(List.copyOf(out), Collections.unmodifiableMap(new LinkedHashMap<>(compiled.utilities())),
				Collections.unmodifiableMap(new LinkedHashMap<>(compiled.transitions())));
	}
}
