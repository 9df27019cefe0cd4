/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.rei.context.Direction;
import org.rei.context.layout.LayoutIssueCodes;
import org.rei.dsl.edit.EditOperation.AddFloor;
import org.rei.dsl.edit.EditOperation.AddWall;
import org.rei.dsl.edit.EditOperation.RemoveFloor;
import org.rei.dsl.edit.EditOperation.RemoveWall;
import org.rei.dsl.edit.diagram.Diagram;

/**
 * Floors and walls of an explicit floor graph (src/test/resources/graph.rei: tabs, comments at line ends and on
 * their own lines, a blank line): added and removed with their neighbour references, nothing else touched.
 */
class FloorGraphEditTest {

	private RoomDocument document;
	private String original;

	@BeforeEach
	void open() throws IOException {
		document = RoomDocument.open(Path.of("src/test/resources/graph.rei"));
		original = document.text();
		assertEquals(List.of(), document.issues());
	}

	@Test
	void theDiagramPlacesTheFloorsAsTheGeneratorsDo() {
		Diagram.Room room = document.diagram().room();
		assertEquals("graph", room.form());
		assertEquals(List.of("A 0,0 0.5", "B 1,0 1.5", "C 2,0 2.5", "D 3,0 3.5"), room.floors().stream()
				.map(f -> f.name() + " " + f.x() + "," + f.y() + " " + f.centreX()).toList());
		Diagram.WallSide wall = room.walls().get(0);
		assertEquals(List.of("W1", "B", "top", 1.5, 1.0), List.of(wall.name(), wall.floor(), wall.side(), wall.x(),
				wall.y()));
	}

	@Test
	void anAddedFloorFollowsTheLastFloorWithTheFilesTabs() {
		AddFloor add = new AddFloor("E", Map.of(Direction.LEFT, "D"));
		EditResult result = document.apply(add);

		assertEquals(List.of("+\t\tfloor E left D"), Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		assertEquals(4.5, document.diagram().room().floors().get(4).centreX());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), add);
	}

	@Test
	void aRemovedFloorTakesTheReferencesToItAlong() {
		EditResult result = document.apply(new RemoveFloor("D"));

		assertEquals(List.of("-\t\tfloor C left B right D", "-\t\tfloor D", "+\t\tfloor C left B"),
				Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), new RemoveFloor("D"));
	}

	@Test
	void aFloorSomethingStandsOnOrAGoalNamesIsKept() {
		EditRefusedException refused = assertThrows(EditRefusedException.class,
				() -> document.apply(new RemoveFloor("A")));
		assertEquals("Floor A is still used by the robot 'tb3', goal 1: move or remove them first",
				refused.getMessage());
		assertEquals(original, document.text());
	}

	@Test
	void aWallIsDeclaredAfterTheLastBlockAndNamedByItsFloor() {
		AddWall add = new AddWall("W2", "D", Direction.RIGHT);
		EditResult result = document.apply(add);

		assertEquals(List.of("-\t\tfloor D", "+\t\tfloor D right W2", "+\t\twall W2"),
				Texts.diff(original, result.text()));
		assertTrue(result.text().contains("\t\tfloor D right W2\n\t\twall W1\n\t\twall W2\n\t\t// the chair stays\n"),
				result.text());
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), add);
	}

	@Test
	void aBatchThatAddsAFloorAndAWallOnItKeepsTheRestOfTheRoom() {
		List<EditOperation> batch = List.of(new AddFloor("E", Map.of(Direction.LEFT, "D")),
				new AddWall("W_E_top", "E", Direction.TOP));
		EditResult result = document.apply(batch);

		assertEquals(List.of("+\t\tfloor E left D top W_E_top", "+\t\twall W_E_top"),
				Texts.diff(original, result.text()));
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), batch.toArray(EditOperation[]::new));

		EditResult removed = document.apply(new RemoveWall("W_E_top"), new RemoveFloor("E"));
		assertEquals(original, removed.text());
	}

	@Test
	void aTakenSideIsRefused() {
		// C names D on its right; D's left is C although D does not say so
		EditRefusedException refused = assertThrows(EditRefusedException.class,
				() -> document.apply(new AddWall("W2", "D", Direction.LEFT)));
		assertEquals("The left side of floor D is C already: remove it first", refused.getMessage());
	}

	@Test
	void aRemovedWallLeavesItsFloorsLineTidy() {
		EditResult result = document.apply(new RemoveWall("W1"));

		assertEquals(List.of("-\t\tfloor B left A top W1", "+\t\tfloor B left A", "-\t\twall W1"),
				Texts.diff(original, result.text()));
		assertTrue(result.text().contains("// the entrance\n\t\tfloor B left A\n\n\t\t/* the far end */\n"),
				result.text());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), new RemoveWall("W1"));
	}

	@Test
	void aFloorCutOffFromTheOthersIsTheLayoutsError() {
		EditResult result = document.apply(new AddFloor("Island", Map.of()));

		ValidationIssue issue = result.issues().get(0);
		assertEquals(LayoutIssueCodes.DISCONNECTED, issue.code());
		assertEquals("Island", issue.element());
		assertEquals("floor", issue.kind());
		assertEquals(10, issue.line());
		assertEquals(9, issue.column());
	}
}
