/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.fuzz;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.rei.fuzz.Mutations;
import org.rei.fuzz.TextFuzzer;
import org.rei.vepl.compiler.DrlTarget;
import org.rei.vepl.compiler.VeplCompiler;
import org.rei.vepl.compiler.VeplLoader;
import org.rei.vepl.validation.KnownQueries;

/**
 * The VEPL front end (parse, validate, compile to DRL - what {@code rei run --patterns} and the monitor's
 * {@code --compile-only} run) under the harness the DSL's fuzz test uses: seeded mutations of the default patterns
 * and the invalid test files. No exception may escape and every error names a line and column inside the input.
 */
class VeplFuzzTest {

	private static final String NAME = "fuzz.vepl";
	private static final Pattern ERROR = Pattern.compile("^  " + Pattern.quote(NAME) + ":(\\d+):(\\d+): (.+)$");

	/** Loads one text as the only pattern file; true when it compiles. */
	static boolean compile(String text, Set<String> queries) {
		try {
			VeplCompiler.compile(VeplLoader.load(List.of(new VeplLoader.Source(NAME, text)), queries), DrlTarget.MONITOR);
			return true;
		} catch (VeplLoader.VeplException e) {
			String[] lines = e.getMessage().split("\n");
			if (lines.length < 2) {
				throw new AssertionError("an error list without errors: " + e.getMessage());
			}
			for (int i = 1; i < lines.length; i++) {
				Matcher m = ERROR.matcher(lines[i]);
				if (!m.matches()) {
					throw new AssertionError("an error without file:line:column: " + lines[i]);
				}
				TextFuzzer.assertPlaced(text, Integer.valueOf(m.group(1)), Integer.valueOf(m.group(2)), m.group(3), lines[i]);
			}
			return false;
		}
	}

	/** VEPL's own mutation: a window or multiplicity at the extremes. */
	static String[] bounds(String text, Random r) {
		String[] windows = { "[0]", "[1]", "[2147483647]", "[99999999999]", "[-1]", "{0}", "{2147483647}", "{+}", "{*}" };
		Matcher m = Pattern.compile("\\[\\d+\\]|\\{(\\d+|\\+|\\*)\\}").matcher(text);
		List<int[]> spans = new ArrayList<>();
		while (m.find()) {
			spans.add(new int[] { m.start(), m.end() });
		}
		if (spans.isEmpty()) {
			return new String[] { "bounds", text };
		}
		int[] s = spans.get(r.nextInt(spans.size()));
		return new String[] { "bounds", text.substring(0, s[0]) + windows[r.nextInt(windows.length)] + text.substring(s[1]) };
	}

	static List<String[]> specials() {
		String chain = "queryEvent a as robotFar found\n" + "complexEvent c0() { as a }\n";
		StringBuilder deep = new StringBuilder(chain);
		for (int i = 1; i < 300; i++) {
			deep.append("complexEvent c").append(i).append("() { as c").append(i - 1).append(" -> a }\n");
		}
		return List.of(new String[] { "empty", "" }, new String[] { "comments", "// nothing\n/* at all */" },
				new String[] { "header-only", "package a.b\nimport-queries a.b.*\n" },
				new String[] { "action-block", "queryEvent a as robotFar found\nrule r on a { if (x) { y() } }\n" },
				new String[] { "deep-chain", deep + "signal S\nrule \"r\" on c299 emits S\n" },
				new String[] { "nested-parens", "queryEvent a as robotFar found\ncomplexEvent c() { as "
						+ "(".repeat(2000) + "a" + ")".repeat(2000) + " }\n" },
				new String[] { "nul", "\0\0\0" });
	}

	@Test
	void mutatedPatternsNeverCrashOrHangAndEveryErrorIsPlaced() throws IOException {
		Path root = TextFuzzer.repositoryRoot("queries");
		Set<String> queries = KnownQueries.inFolder(root.resolve("queries"));
		List<String> seeds = TextFuzzer.files(List.of(root.resolve("cep/patterns"),
				root.resolve("cep/org.rei.vepl/src/test/resources/invalid")), ".vepl");
		try (TextFuzzer fuzzer = new TextFuzzer(text -> compile(text, queries), seeds, specials(),
				new Mutations(VeplFuzzTest::bounds), 10_000)) {
			TextFuzzer.Result r = fuzzer.run(20261124L, 400, 90);
			System.out.println("VEPL fuzz: " + r.inputs() + " inputs, " + r.valid() + " valid, by mutation "
					+ r.byMutation());
			assertTrue(r.failures().isEmpty(), () -> r.failures().size() + " failures, first: " + r.failures().get(0)
					+ "\n" + r.failures().get(0).input());
			assertTrue(r.inputs() > 300, "too few inputs in the time box: " + r.inputs());
			assertTrue(r.valid() >= seeds.size() / 3, "the valid seeds should compile: " + r.valid());
		}
	}
}
