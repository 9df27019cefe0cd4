/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class MainTest {

	private static final String VALID = """
			testcase T {
			  room R size 3 x 2 {
			    object crate : Box on F_1_0
			    robot r : Waffle on F_0_0
			  }
			  mission M { goto F_1_1 goto F_2_1 }
			}
			""";

	@TempDir
	Path dir;

	private final ByteArrayOutputStream out = new ByteArrayOutputStream();
	private final ByteArrayOutputStream err = new ByteArrayOutputStream();

	private int run(String... args) {
		return new Main(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8))
				.run(args);
	}

	private Path write(String name, String text) throws IOException {
		return Files.writeString(dir.resolve(name), text);
	}

	@Test
	void validFileValidatesAndGeneratesAllArtifacts() throws IOException {
		Path file = write("ok.rei", VALID);
		assertEquals(Main.OK, run("validate", file.toString()));
		Path outDir = dir.resolve("out");
		assertEquals(Main.OK, run("generate", file.toString(), "-o", outDir.toString()));
		for (String artifact : List.of("world.sdf", "world.json", "mission.xml", "animation.json", "monitor.json")) {
			assertTrue(Files.size(outDir.resolve(artifact)) > 0, artifact);
		}
	}

	@Test
	void invalidFileExitsOneWithFileLineColumn() throws IOException {
		Path file = write("bad.rei", VALID.replace("on F_1_0", "on F_9_9"));
		assertEquals(Main.INVALID, run("generate", file.toString(), "-o", dir.resolve("out").toString()));
		String errors = err.toString(StandardCharsets.UTF_8);
		assertTrue(errors.contains(file + ":3:27: error: Unknown floor 'F_9_9'"), errors);
		assertTrue(Files.notExists(dir.resolve("out/world.sdf")), "nothing generated from an invalid file");
	}

	@Test
	void missingFileAndBadUsageExitTwo() {
		assertEquals(Main.USAGE, run("validate", dir.resolve("nope.rei").toString()));
		assertTrue(err.toString(StandardCharsets.UTF_8).contains("cannot read"));
		assertEquals(Main.USAGE, run("generate", "x.rei"));
		assertTrue(err.toString(StandardCharsets.UTF_8).contains("-o OUTDIR"));
		assertEquals(Main.USAGE, run("frobnicate", "x.rei"));
		assertEquals(Main.USAGE, run("validate", "notes.txt"));
	}

	@Test
	void repeatPrintsOneTimingPerIteration() throws IOException {
		Path file = write("ok.rei", VALID);
		assertEquals(Main.OK, run("validate", file.toString(), "--repeat", "3", "--quiet"));
		assertEquals(3, out.toString(StandardCharsets.UTF_8).lines().filter(l -> l.startsWith("iteration ")).count());
	}
}
