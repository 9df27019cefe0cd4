/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.context.Direction;
import org.rei.dsl.edit.EditOperation.AddGoal;
import org.rei.dsl.edit.EditOperation.AddHuman;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.EditOperation.AddWall;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.Waypoint;
import org.rei.dsl.edit.diagram.Diagram;

/**
 * A room from an occupancy map (the DSL tests' 12 x 8 cell map, six free blocks of 0.2 m) is edited like every
 * other room: furniture, humans and goals on its free floors, saved through the serializer without touching the map
 * line.
 */
class MapRoomEditTest {

	private static final String TEXT = """
			testcase T {
			  // the map's YAML is beside this file
			  room R occupancy "small.yaml" unknownFree floorSize 0.2 {
			    object crate : Box on F_4_2
			    robot r : Waffle on F_2_1
			  }
			  mission M { goto F_4_1 goto F_2_2 }
			}
			""";

	private static Path write(Path folder) throws IOException {
		Path maps = Texts.repository().resolve("bundles/org.rei.dsl/src/test/resources/maps");
		Files.copy(maps.resolve("small.yaml"), folder.resolve("small.yaml"));
		Files.copy(maps.resolve("small.pgm"), folder.resolve("small.pgm"));
		Path file = folder.resolve("room.rei");
		Files.writeString(file, TEXT);
		return file;
	}

	@Test
	void furnitureAndGoalsAreSavedThroughTheSerializer(@TempDir Path folder) throws IOException {
		RoomDocument document = RoomDocument.open(write(folder));
		String original = document.text();
		List<EditOperation> batch = List.of(new AddObject("bin", "Bin", "F_3_2"), new MoveObject("r", "F_3_1"),
				new AddGoal("F_1_2", 2, null));
		EditResult result = document.apply(batch);

		assertEquals(List.of("-    robot r : Waffle on F_2_1", "+    object bin : Bin on F_3_2",
				"+    robot r : Waffle on F_3_1", "-  mission M { goto F_4_1 goto F_2_2 }",
				"+  mission M { goto F_4_1 goto F_2_2 goto F_1_2 }"), Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		assertTrue(result.text().contains("  room R occupancy \"small.yaml\" unknownFree floorSize 0.2 {\n"),
				result.text());
		assertTrue(!result.text().contains("floor F"), "the map's floors stay derived: " + result.text());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), batch.toArray(EditOperation[]::new));

		assertEquals("occupancy", document.diagram().room().form());
		assertEquals(7, document.diagram().room().floors().size());
		assertEquals(List.of(), document.diagram().room().walls());
		Diagram.OccupancyMap map = document.diagram().room().map();
		assertEquals(List.of(folder.resolve("small.pgm").toString(), 0.1, -0.6, 0.4, 12, 8, true), List.of(map.image(),
				map.resolution(), map.originX(), map.originY(), map.width(), map.height(), map.unknownFree()));
		Diagram.FloorCell f31 = document.diagram().room().floors().stream().filter(f -> f.name().equals("F_3_1"))
				.findFirst().orElseThrow();
		// in the map's frame: origin (-0.6, 0.4) + (3.5, 1.5) * 0.2
		assertEquals(0.1, f31.centreX(), 1e-9);
		assertEquals(0.7, f31.centreY(), 1e-9);
		assertEquals(original, document.undo().text());
	}

	@Test
	void aHumanWalksTheMapsFreeFloorsAndIsSavedAndReadBack(@TempDir Path folder) throws IOException {
		Path file = write(folder);
		RoomDocument document = RoomDocument.open(file);
		String original = document.text();
		// the free blocks of the map are F_2_1..F_4_1 and F_1_2..F_4_2; F_1_1 is on its wall
		assertThrows(EditRefusedException.class, () -> document.apply(new AddHuman("lost", null,
				List.of(new Waypoint("F_1_2", 0), new Waypoint("F_1_1", 3)), true)));
		AddHuman add = new AddHuman("visitor", null, List.of(new Waypoint("F_1_2", 0), new Waypoint("F_3_2", 4),
				new Waypoint("F_3_1", 6.5)), true);
		EditResult result = document.apply(add);

		assertEquals(List.of("+    human visitor trajectory [F_1_2 @ 0s, F_3_2 @ 4s, F_3_1 @ 6.5s] loop"),
				Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), add);

		document.save();
		RoomDocument reopened = RoomDocument.open(file);
		assertEquals(result.text(), Files.readString(file));
		assertEquals(List.of(), reopened.issues());
		assertEquals("occupancy", reopened.diagram().room().form());
		Diagram.Mover visitor = reopened.diagram().movers().stream().filter(m -> m.name().equals("visitor"))
				.findFirst().orElseThrow();
		assertEquals(List.of("human", "Human", true), List.of(visitor.kind(), visitor.footprint().type(),
				visitor.loop()));
		// in the map's frame: origin (-0.6, 0.4) + (3.5, 2.5) * 0.2
		assertEquals(new Diagram.Waypoint("F_3_2", 4, 0.1, 0.9), roundedPoint(visitor.points().get(1)));
		assertEquals(List.of("F_1_2", "F_3_2", "F_3_1"), visitor.points().stream().map(Diagram.Waypoint::floor)
				.toList());
	}

	/** A waypoint with its centre rounded to micrometres: the map's frame is sums of decimal fractions. */
	private static Diagram.Waypoint roundedPoint(Diagram.Waypoint point) {
		return new Diagram.Waypoint(point.floor(), point.seconds(), Math.round(point.x() * 1e6) / 1e6,
				Math.round(point.y() * 1e6) / 1e6);
	}

	@Test
	void aFloorSizeTypedOnTheWayToAnotherIsAnIssueOnTheNumberNotAFailure(@TempDir Path folder) throws IOException {
		RoomDocument document = RoomDocument.open(write(folder));
		// the text saved by a text editor while its user types 0.0000001 on the way to 0.05
		EditResult typing = document.reset(TEXT.replace("floorSize 0.2", "floorSize 0.0000001"));
		List<ValidationIssue> errors = typing.issues().stream().filter(ValidationIssue::isError).toList();
		assertEquals(1, errors.size(), () -> "one error, on the floor size: " + errors);
		ValidationIssue error = errors.get(0);
		assertEquals(List.of(3, 55, "org.rei.dsl.roomTooLarge"), List.of(error.line(), error.column(), error.code()));
		assertTrue(error.message().startsWith("floorSize 0.0000001 m cuts the map small.yaml (12 x 8 cells of 0.1 m) "
				+ "into 12000000 x 8000000 blocks"), error.message());
		assertEquals(List.of(), document.diagram().room().floors(), "no floors, and a diagram all the same");
		assertEquals(List.of(), document.reset(TEXT.replace("floorSize 0.2", "floorSize 0.05")).issues().stream()
				.filter(ValidationIssue::isError).map(ValidationIssue::code).filter(c -> c.endsWith("roomTooLarge"))
				.toList());
		assertEquals(List.of(), document.reset(TEXT).issues());
		assertEquals(7, document.diagram().room().floors().size());
	}

	@Test
	void aMapRoomRefusesWalls(@TempDir Path folder) throws IOException {
		RoomDocument document = RoomDocument.open(write(folder));
		EditRefusedException refused = assertThrows(EditRefusedException.class,
				() -> document.apply(new AddWall("W", "F_2_1", Direction.LEFT)));
		assertEquals("Cannot add wall W: room 'R' derives its floors from the occupancy map small.yaml; change the "
				+ "map or the floor size", refused.getMessage());
	}
}
