/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.rei.context.Direction;
import org.rei.dsl.edit.EditOperation.AddFloor;
import org.rei.dsl.edit.EditOperation.AddGoal;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.EditOperation.DeleteObject;
import org.rei.dsl.edit.EditOperation.MoveGoal;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.RemoveGoal;
import org.rei.dsl.edit.EditOperation.RotateObject;
import org.rei.dsl.edit.EditOperation.SetTrajectory;
import org.rei.dsl.edit.EditOperation.Waypoint;
import org.rei.dsl.validation.ReiIssueCodes;

/**
 * Edits of examples/simple_navigation.rei (a grid room with comments above it): each changes only the text it
 * must, and what it writes reads back as the edited model.
 */
class SimpleNavigationEditTest {

	private RoomDocument document;
	private String original;

	@BeforeEach
	void open() {
		document = Texts.open("examples/simple_navigation.rei");
		original = document.text();
		assertEquals(List.of(), document.issues());
	}

	@Test
	void movingAnObjectReplacesOnlyTheFloorName() {
		EditResult result = document.apply(new MoveObject("table1", "F_3_3"));

		int at = original.indexOf("F_2_1");
		assertEquals(List.of(new TextEdit(at, 5, "F_3_3")), result.edits());
		assertEquals(List.of("-    object table1 : Table on F_2_1", "+    object table1 : Table on F_3_3"),
				Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		assertEquals("F_3_3", document.diagram().objects().get(0).floor());
		assertEquals(3.5, document.diagram().objects().get(0).x());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), new MoveObject("table1", "F_3_3"));
	}

	@Test
	void addingAGoalInsertsOneLineIndentedLikeTheOthers() {
		EditResult result = document.apply(new AddGoal("F_2_2", 1));

		assertEquals(List.of("+    goto F_2_2"), Texts.diff(original, result.text()));
		assertEquals(1, result.edits().size());
		assertTrue(result.text().contains("    goto F_4_0\n    goto F_2_2\n    goto F_5_3\n"), result.text());
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), new AddGoal("F_2_2", 1));
	}

	@Test
	void aGoalWithItsOwnTimeoutIsAppended() {
		EditResult result = document.apply(new AddGoal("F_0_3", 2, 45.0));

		assertEquals(List.of("+    goto F_0_3 within 45s"), Texts.diff(original, result.text()));
		// F_0_3 carries shelf1: the mission validator says so on the new goal
		ValidationIssue issue = result.issues().get(0);
		assertEquals(List.of(ReiIssueCodes.GOAL_OCCUPIED), codes(result));
		assertEquals("goal", issue.kind());
		assertEquals("F_0_3", issue.element());
		assertEquals(2, issue.index());
		assertEquals(13, issue.line());
		assertEquals(10, issue.column());
	}

	@Test
	void aTrajectoryEditChangesOnlyThatHumansLine() {
		List<Waypoint> points = List.of(new Waypoint("F_1_2", 0), new Waypoint("F_3_1", 5.5));
		EditResult result = document.apply(new SetTrajectory("walker", points, false));

		assertEquals(List.of("-    human walker trajectory [F_1_2 @ 0s, F_3_2 @ 6s, F_4_2 @ 9s] loop",
				"+    human walker trajectory [F_1_2 @ 0s, F_3_1 @ 5.5s]"), Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(),
				new SetTrajectory("walker", points, false));
	}

	@Test
	void aChangedTimeReplacesJustThatTime() {
		List<Waypoint> points = List.of(new Waypoint("F_1_2", 0), new Waypoint("F_3_2", 7), new Waypoint("F_4_2", 9));
		EditResult result = document.apply(new SetTrajectory("walker", points, true));

		assertEquals(List.of(new TextEdit(original.indexOf("6s"), 2, "7s")), result.edits());
	}

	@Test
	void deletingAnObjectRemovesItsLine() {
		EditResult result = document.apply(new DeleteObject("shelf1"));

		assertEquals(List.of("-    object shelf1 : Shelf on F_0_3"), Texts.diff(original, result.text()));
		assertEquals(1, result.edits().size());
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), new DeleteObject("shelf1"));
	}

	/** PlacementValidator.checkOneObjectPerFloor: the later of two objects on one floor is in error. */
	@Test
	void twoObjectsOnOneFloorAreReportedOnTheLaterOne() {
		EditResult result = document.apply(new AddObject("box1", "Box", "F_2_1"));

		assertEquals(List.of("+    object box1 : Box on F_2_1"), Texts.diff(original, result.text()));
		assertEquals(1, result.issues().size(), () -> result.issues().toString());
		ValidationIssue issue = result.issues().get(0);
		assertEquals(ReiIssueCodes.FLOOR_OCCUPIED, issue.code());
		assertEquals("error", issue.severity());
		assertEquals("box1", issue.element());
		assertEquals("object", issue.kind());
		assertEquals(8, issue.line());
		assertEquals(26, issue.column());
		assertTrue(issue.message().contains("already taken by 'table1'"), issue.message());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), new AddObject("box1", "Box", "F_2_1"));
	}

	@Test
	void movingOntoAnotherObjectsFloorIsReportedOnTheMovedOne() {
		EditResult result = document.apply(new MoveObject("shelf1", "F_2_1"));

		ValidationIssue issue = result.issues().get(0);
		assertEquals(List.of(ReiIssueCodes.FLOOR_OCCUPIED), codes(result));
		assertEquals("shelf1", issue.element());
		assertEquals(6, issue.line());
		assertEquals(30, issue.column());
	}

	@Test
	void turningAnObjectAppendsItsYawAndZeroRemovesIt() {
		EditResult turned = document.apply(new RotateObject("table1", 45));
		assertEquals(List.of("-    object table1 : Table on F_2_1", "+    object table1 : Table on F_2_1 yaw 45"),
				Texts.diff(original, turned.text()));

		EditResult back = document.apply(new RotateObject("table1", 0));
		assertEquals(original, back.text());
	}

	@Test
	void aBatchIsOneChangeAndOneUndoStep() {
		List<EditOperation> batch = List.of(new AddObject("box1", "Box", "F_1_1"), new MoveGoal(1, 0),
				new RemoveGoal(1), new RotateObject("tb3", 90));
		EditResult result = document.apply(batch);

		String expected = original
				.replace("    robot tb3 : Waffle on F_0_0\n",
						"    object box1 : Box on F_1_1\n    robot tb3 : Waffle on F_0_0 yaw 90\n")
				.replace("    goto F_4_0\n    goto F_5_3\n", "    goto F_5_3\n");
		assertEquals(expected, result.text());
		// the goal that stayed keeps its text: only the other one is deleted
		assertEquals(3, result.edits().size(), () -> result.edits().toString());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), batch.toArray(EditOperation[]::new));

		EditResult undone = document.undo();
		assertEquals(original, undone.text());
		assertEquals(original, document.text());
		assertEquals(result.text(), document.redo().text());
	}

	@Test
	void undoAppliesTheInverseEditsAndRedoTheEditsAgain() {
		EditResult moved = document.apply(new MoveObject("table1", "F_3_3"));
		assertTrue(document.canUndo());

		EditResult undone = document.undo();
		int at = original.indexOf("F_2_1");
		assertEquals(List.of(new TextEdit(at, 5, "F_2_1")), undone.edits());
		assertEquals(original, undone.text());
		assertFalse(document.canUndo());

		assertEquals(moved.text(), document.redo().text());
		assertEquals("F_3_3", document.diagram().objects().get(0).floor());
	}

	@Test
	void whatTheTextCannotSayIsRefusedAndChangesNothing() {
		assertRefused(new MoveObject("table1", "F_9_9"), "no floor or wall named 'F_9_9'");
		assertRefused(new MoveObject("walker", "F_1_1"), "change its trajectory instead");
		assertRefused(new AddObject("shelf1", "Box", "F_1_1"), "The name 'shelf1' is taken");
		assertRefused(new AddObject("room", "Box", "F_1_1"), "'room' is not a name");
		assertRefused(new AddObject("box1", "Sofa", "F_1_1"), "No type 'Sofa'");
		assertRefused(new DeleteObject("tb3"), "a room has exactly one");
		assertRefused(new AddFloor("F_6_0", Map.of(Direction.LEFT, "F_5_0")), "derives its floors and walls from "
				+ "its size 6 x 4");
		assertRefused(new RemoveGoal(2), "No goal 2");
		assertRefused(new SetTrajectory("walker", List.of(), true), "'walker' would have none");
		// a refusal late in a batch undoes the earlier operations of the batch too
		assertRefused(List.of(new MoveObject("table1", "F_3_3"), new MoveGoal(0, 5)), "cannot move to 5");
		assertEquals("F_2_1", document.diagram().objects().get(0).floor());
	}

	@Test
	void aTextChangedElsewhereReplacesTheModelAndTheHistory() {
		String moved = document.apply(new MoveObject("table1", "F_3_3")).text();
		String typed = original.replace("goto F_5_3", "goto F_5_2");

		EditResult result = document.reset(typed);

		assertEquals(typed, TextEdits.apply(moved, result.edits()));
		assertEquals(typed, result.text());
		assertEquals("F_5_2", document.diagram().mission().goals().get(1).floor());
		assertEquals("F_2_1", document.diagram().objects().get(0).floor());
		assertFalse(document.canUndo());
	}

	private void assertRefused(EditOperation operation, String message) {
		assertRefused(List.of(operation), message);
	}

	private void assertRefused(List<EditOperation> operations, String message) {
		EditRefusedException refused = assertThrows(EditRefusedException.class, () -> document.apply(operations));
		assertTrue(refused.getMessage().contains(message), refused.getMessage());
		assertEquals(original, document.text());
		assertFalse(document.canUndo());
	}

	private static List<String> codes(EditResult result) {
		return result.issues().stream().map(ValidationIssue::code).toList();
	}
}
