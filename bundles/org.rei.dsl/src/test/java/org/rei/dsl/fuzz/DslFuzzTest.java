/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.fuzz;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;

import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.rei.dsl.validation.ReiIssueCodes;
import org.rei.fuzz.TextFuzzer;

/** A short, seeded campaign of {@link DslFuzzer}: no crash, no hang, every issue placed inside the input. */
class DslFuzzTest {

	@Test
	void mutatedTestCasesNeverCrashOrHang() throws IOException {
		try (DslFuzzer fuzzer = new DslFuzzer(DslFuzzer.defaultSeeds(), 10_000)) {
			// a fixed number of inputs keeps it deterministic; the time box only guards a slow machine
			TextFuzzer.Result r = fuzzer.run(20261122L, 300, 60);
			System.out.println("DSL fuzz: " + r.inputs() + " inputs, " + r.valid() + " valid, by mutation "
					+ r.byMutation());
			assertTrue(r.failures().isEmpty(), () -> r.failures().size() + " failures " + r.failures() + ", first: "
					+ r.failures().get(0) + "\n" + abbreviate(r.failures().get(0).input()));
			assertTrue(r.inputs() > 200, "too few inputs in the time box: " + r.inputs());
		}
	}

	/** Regression: a grid size or map from the text was allocated as is (size 100000 x 100000: 10^10 cells). */
	@Test
	void hugeRoomsAreRefusedWithoutBeingBuilt() throws IOException {
		String tail = " {\n    robot r : Waffle on F_0_0\n  }\n  mission M { goto F_1_1 goto F_2_2 }\n}\n";
		try (DslFuzzer fuzzer = new DslFuzzer(List.of(), 10_000)) {
			for (String layout : List.of("size 100000 x 100000", "size 2147483647 x 2", "size 201 x 200",
					"map \"" + ".".repeat(50_000) + "\n\n.\"")) {
				long start = System.nanoTime();
				List<Issue> issues = fuzzer.issues("testcase T {\n  room R " + layout + tail);
				assertTrue(issues.stream().anyMatch(i -> ReiIssueCodes.ROOM_TOO_LARGE.equals(i.getCode())
						&& i.getLineNumber() == 2), () -> layout.substring(0, 20) + ": " + issues);
				assertTrue(System.nanoTime() - start < 5e9, "took " + (System.nanoTime() - start) / 1e9 + " s");
			}
			assertTrue(fuzzer.issues("testcase T {\n  room R size 200 x 200" + tail).stream()
					.noneMatch(i -> ReiIssueCodes.ROOM_TOO_LARGE.equals(i.getCode())));
		}
	}

	private static String abbreviate(String s) {
		return s.length() > 2000 ? s.substring(0, 2000) + "..." : s;
	}
}
