/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.rei.dsl.validation.ReiIssueCodes;

import com.google.inject.Inject;

/**
 * The floor cap of every room kind is checked with arithmetic that cannot overflow, before anything is allocated:
 * a floor size typed on the way to another ({@code 0.0000001} before {@code 0.05}) or a size from a few bytes of
 * text is a positioned error (or, where the floor count does not depend on it, nothing), never an exception that
 * takes the validation, the editor's server or the other files of {@code rei validate} with it.
 */
@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class FloorCapTest {

	private static final Path SMALL = Path.of("src/test/resources/maps/small.yaml").toAbsolutePath();

	@Inject
	private ReiFiles files;

	private List<Issue> errors(Path folder, String text) throws Exception {
		Path file = Files.writeString(folder.resolve("room.rei"), text);
		return files.validate(file).stream().filter(i -> i.getSeverity() == Severity.ERROR).toList();
	}

	private static String room(String kind, String floorSize) {
		String head = switch (kind) {
		case "grid" -> "room R size 3 x 2 floorSize " + floorSize + " {";
		case "ascii" -> "room R floorSize " + floorSize + " map \"\n...\n...\n\" {";
		case "graph" -> "room R floorSize " + floorSize
				+ " {\n    floor F_0_0 right F_1_0\n    floor F_1_0 right F_2_0\n    floor F_2_0";
		case "occupancy" -> "room R occupancy \"" + SMALL + "\" floorSize " + floorSize + " {";
		default -> throw new IllegalArgumentException(kind);
		};
		// F_2_1 and F_4_1 are free blocks of small.yaml at 0.2 m, and floors of the others but the graph
		String floors = kind.equals("occupancy") ? "F_4_1 goto F_2_2" : kind.equals("graph") ? "F_2_0 goto F_1_0"
				: "F_2_1 goto F_1_1";
		return "testcase T {\n  " + head + "\n    robot r : Waffle on " + (kind.equals("occupancy") ? "F_2_1" : "F_0_0")
				+ "\n  }\n  mission M { goto " + floors + " }\n}\n";
	}

	@ParameterizedTest(name = "{0}")
	@ValueSource(strings = { "grid", "ascii", "graph", "occupancy" })
	void aTinyFloorSizeIsAPositionedErrorOrNothingInEveryRoomKind(String kind, @TempDir Path folder)
			throws Exception {
		List<Issue> fine = errors(folder, room(kind, "0.2"));
		assertEquals(List.of(), fine, kind + " at 0.2 m");
		List<Issue> tiny = errors(folder, room(kind, "0.0000001"));
		if (!kind.equals("occupancy")) {
			// grids, drawn maps and floor graphs have as many floors whatever their size
			assertEquals(List.of(), tiny, kind + " at 0.0000001 m");
			return;
		}
		assertEquals(1, tiny.size(), () -> "one error, on the floor size, and none for each floor named: " + tiny);
		Issue error = tiny.get(0);
		assertEquals(List.of(2, 2 + "room R occupancy \"".length() + SMALL.toString().length() + "\" floorSize ".length()
				+ 1, ReiIssueCodes.ROOM_TOO_LARGE), List.of(error.getLineNumber(), error.getColumn(), error.getCode()));
		assertEquals("floorSize 0.0000001 m cuts the map " + SMALL + " (12 x 8 cells of 0.1 m) into 12000000 x 8000000"
				+ " blocks: a room's map may be cut into at most 4000000 blocks (free or not); use a larger floorSize",
				error.getMessage());
	}

	@Test
	void aGridsFloorCountIsCountedInLongs(@TempDir Path folder) throws Exception {
		List<Issue> huge = errors(folder, "testcase T {\n  room R size 2147483647 x 2147483647 {\n"
				+ "    robot r : Waffle on F_0_0\n  }\n  mission M { goto F_1_0 goto F_0_1 }\n}\n");
		assertEquals(List.of("A room may have at most 40000 floors, this one has 4611686014132420609"),
				huge.stream().filter(i -> ReiIssueCodes.ROOM_TOO_LARGE.equals(i.getCode())).map(Issue::getMessage)
						.toList());
	}
}
