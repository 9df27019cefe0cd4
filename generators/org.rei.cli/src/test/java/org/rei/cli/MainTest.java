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

	/** examples/maps/two_rooms.rei, its map beside it, with {@code floorSize} replaced. */
	private Path twoRooms(String name, String floorSize) throws IOException {
		Path examples = Path.of("../../examples/maps").toAbsolutePath().normalize();
		for (String file : List.of("two_rooms.yaml", "two_rooms.pgm")) {
			if (Files.notExists(dir.resolve(file))) {
				Files.copy(examples.resolve(file), dir.resolve(file));
			}
		}
		return write(name, Files.readString(examples.resolve("two_rooms.rei")).replace("floorSize 0.5",
				"floorSize " + floorSize));
	}

	@Test
	void aTinyFloorSizeIsAPositionedErrorAndTheOtherFilesAreStillReported() throws IOException {
		Path tiny = twoRooms("tiny.rei", "0.0000001");
		Path bad = write("bad.rei", VALID.replace("on F_1_0", "on F_9_9"));
		Path ok = write("ok.rei", VALID);
		assertEquals(Main.INVALID, run("validate", tiny.toString(), bad.toString(), ok.toString()));
		String errors = err.toString(StandardCharsets.UTF_8);
		assertTrue(errors.contains(tiny + ":5:52: error: floorSize 0.0000001 m cuts the map two_rooms.yaml (200 x 120 "
				+ "cells of 0.05 m) into 100000000 x 60000000 blocks: a room's map may be cut into at most 4000000 blocks"
				+ " (free or not); use a larger floorSize [org.rei.dsl.roomTooLarge]"), errors);
		assertTrue(errors.contains(bad + ":3:27: error: Unknown floor 'F_9_9'"), errors);
		assertEquals(2, errors.lines().count(), errors);

		Path out = dir.resolve("out");
		assertEquals(Main.INVALID, run("generate", tiny.toString(), "-o", out.toString()));
		assertTrue(Files.notExists(out.resolve("world.json")), "nothing generated");
		assertEquals(Main.OK, run("generate", twoRooms("fine.rei", "0.5").toString(), "-o", out.toString()));
	}

	@Test
	void aFileWhoseCheckFailsUnexpectedlyIsThatFilesErrorAndTheOthersAreStillChecked() throws IOException {
		Path first = write("first.rei", VALID.replace("on F_1_0", "on F_9_9"));
		Path failing = write("failing.rei", VALID);
		Path last = write("last.rei", VALID.replace("goto F_2_1", "goto F_8_8"));
		// a bug of REI's own in the checking of one file, as a NegativeArraySizeException from the map reader was
		Main main = new Main(new PrintStream(out, true, StandardCharsets.UTF_8),
				new PrintStream(err, true, StandardCharsets.UTF_8), templates -> new HeadlessGenerator(templates) {
					@Override
					public Result validate(Path file) {
						if (file.equals(failing)) {
							throw new NegativeArraySizeException("-593035264");
						}
						return super.validate(file);
					}
				});
		assertEquals(Main.INVALID, main.run(new String[] { "validate", first.toString(), failing.toString(),
				last.toString() }));
		List<String> errors = err.toString(StandardCharsets.UTF_8).lines().toList();
		assertEquals(3, errors.size(), errors::toString);
		assertTrue(errors.get(0).startsWith(first + ":3:27: error: Unknown floor 'F_9_9'"), errors::toString);
		assertTrue(errors.get(1).startsWith(failing + ":1:1: error: internal error while checking this file, please "
				+ "report it: java.lang.NegativeArraySizeException: -593035264 at org.rei.cli.MainTest"),
				errors::toString);
		assertTrue(errors.get(1).endsWith(" [" + Main.INTERNAL_ERROR + "]"), errors::toString);
		assertTrue(errors.get(2).startsWith(last + ":6:"), errors::toString);
	}
}
