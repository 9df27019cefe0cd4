/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.compiler;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Ahead-of-time compilation (the Maven build of the monitor runs it):
 * {@code VeplMain --queries QUERIES_DIR --out OUT_DIR PATTERN_DIR...} writes the .drl files and
 * {@code signals.properties} (signal = default utility). Exit 0 done, 1 invalid patterns, 2 bad command line.
 */
public final class VeplMain {

	private VeplMain() {
	}

	public static void main(String[] args) throws Exception {
		int rc = run(args);
		if (rc != 0) {
			System.exit(rc);
		}
	}

	public static int run(String[] args) throws Exception {
		Path queries = null;
		Path out = null;
		List<Path> dirs = new ArrayList<>();
		for (int i = 0; i < args.length; i++) {
			switch (args[i]) {
			case "--queries" -> queries = Path.of(args[++i]);
			case "--out" -> out = Path.of(args[++i]);
			default -> dirs.add(Path.of(args[i]));
			}
		}
		if (queries == null || out == null || dirs.isEmpty()) {
			System.err.println("usage: VeplMain --queries DIR --out DIR PATTERN_DIR...");
			return 2;
		}
		List<VeplLoader.Source> sources = new ArrayList<>();
		for (Path d : dirs) {
			sources.addAll(VeplLoader.folder(d));
		}
		CompiledRules rules;
		try {
			rules = VeplLoader.compile(sources, org.rei.vepl.validation.KnownQueries.inFolder(queries),
					DrlTarget.MONITOR);
		} catch (VeplLoader.VeplException e) {
			System.err.println(e.getMessage());
			return 1;
		}
		Files.createDirectories(out);
		for (CompiledRules.DrlFile f : rules.files()) {
			Files.writeString(out.resolve(f.name()), f.text(), StandardCharsets.UTF_8);
		}
		Files.writeString(out.resolve("signals.properties"), utilities(rules.utilities()), StandardCharsets.UTF_8);
		return 0;
	}

	/** {@code SIGNAL = utility} lines, in declaration order; a signal without a default utility gets none. */
	public static String utilities(Map<String, Double> utilities) {
		StringBuilder b = new StringBuilder("# default utility of every signal the VEPL patterns publish\n");
		utilities.forEach((k, v) -> b.append(k).append(" = ").append(v == null ? "" : v).append('\n'));
		return b.toString();
	}
}
