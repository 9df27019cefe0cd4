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
import org.rei.dsl.edit.EditOperation.AddDynamic;
import org.rei.dsl.edit.EditOperation.AddFloor;
import org.rei.dsl.edit.EditOperation.AddGoal;
import org.rei.dsl.edit.EditOperation.AddHuman;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.EditOperation.DeleteObject;
import org.rei.dsl.edit.EditOperation.MoveGoal;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.RemoveGoal;
import org.rei.dsl.edit.EditOperation.RotateObject;
import org.rei.dsl.edit.EditOperation.SetTrajectory;
import org.rei.dsl.edit.EditOperation.Waypoint;
import org.rei.dsl.edit.diagram.Diagram;
import org.rei.dsl.edit.diagram.PaletteType;
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
		assertEquals(List.of("table1"), issue.related());
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

	/** Each of three objects on one floor but the first is in error; each error names the other two. */
	@Test
	void aTakenFloorsErrorNamesTheOtherObjectsOnIt() {
		EditResult result = document.apply(new MoveObject("shelf1", "F_2_1"), new AddObject("box1", "Box", "F_2_1"));

		assertEquals(List.of("shelf1 [table1, box1]", "box1 [table1, shelf1]"), result.issues().stream()
				.map(i -> i.element() + " " + i.related()).toList());
		assertEquals(List.of(ReiIssueCodes.FLOOR_OCCUPIED, ReiIssueCodes.FLOOR_OCCUPIED), codes(result));
	}

	@Test
	void aTakenFloorsErrorOnTheRobotOrAHumanNamesTheObject() {
		EditResult robot = document.apply(new MoveObject("table1", "F_0_0"));
		assertEquals(List.of("robot tb3 [table1]"), robot.issues().stream()
				.map(i -> i.kind() + " " + i.element() + " " + i.related()).toList());
		document.undo();

		EditResult human = document.apply(new SetTrajectory("walker", List.of(new Waypoint("F_2_1", 0),
				new Waypoint("F_2_2", 4)), true));
		assertEquals(List.of("human walker [table1]"), human.issues().stream()
				.map(i -> i.kind() + " " + i.element() + " " + i.related()).toList());
		assertEquals(List.of(), document.undo().issues());
	}

	@Test
	void anAddedHumanIsOneNewLineAfterTheOtherObjects() {
		AddHuman add = new AddHuman("visitor", null, List.of(new Waypoint("F_0_1", 0), new Waypoint("F_5_1", 8)),
				true);
		EditResult result = document.apply(add);

		assertEquals(List.of("+    human visitor trajectory [F_0_1 @ 0s, F_5_1 @ 8s] loop"),
				Texts.diff(original, result.text()));
		assertEquals(1, result.edits().size());
		assertEquals(List.of(), result.issues());
		Diagram.Mover visitor = document.diagram().movers().get(1);
		assertEquals(List.of("visitor", "human", "Human", true), List.of(visitor.name(), visitor.kind(),
				visitor.footprint().type(), visitor.loop()));
		assertEquals(new Diagram.Waypoint("F_5_1", 8, 5.5, 1.5), visitor.points().get(1));
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), add);
		assertEquals(original, document.undo().text());
	}

	@Test
	void anAddedHumanOfANamedTypeThatWalksOnce() {
		AddHuman add = new AddHuman("visitor", "Human", List.of(new Waypoint("F_0_1", 0), new Waypoint("F_5_1", 8.5),
				new Waypoint("F_5_2", 10)), false);
		EditResult result = document.apply(add);

		assertEquals(List.of("+    human visitor : Human trajectory [F_0_1 @ 0s, F_5_1 @ 8.5s, F_5_2 @ 10s]"),
				Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), add);
	}

	@Test
	void aHumanTheTextCannotSayIsRefused() {
		List<Waypoint> points = List.of(new Waypoint("F_0_1", 0), new Waypoint("F_5_1", 8));
		assertRefused(new AddHuman("walker", null, points, true), "The name 'walker' is taken");
		assertRefused(new AddHuman("visitor", "Robot", points, true), "No type 'Robot'");
		assertRefused(new AddHuman("visitor", null, List.of(new Waypoint("F_7_1", 0)), true),
				"no floor or wall named 'F_7_1'");
		assertRefused(new AddHuman("visitor", null, List.of(), true), "human 'visitor' would have none");
	}

	@Test
	void anAddedMovingObjectIsOneNewLineAfterTheOtherObjects() {
		AddDynamic add = new AddDynamic("cart1", "Cart", List.of(new Waypoint("F_1_1", 0), new Waypoint("F_3_1", 2),
				new Waypoint("F_3_3", 4)), false);
		EditResult result = document.apply(add);

		assertEquals(List.of("+    dynamic cart1 : Cart trajectory [F_1_1 @ 0s, F_3_1 @ 2s, F_3_3 @ 4s]"),
				Texts.diff(original, result.text()));
		assertEquals(1, result.edits().size());
		Diagram.Mover cart = document.diagram().movers().get(1);
		assertEquals(List.of("cart1", "dynamic", "Cart", false), List.of(cart.name(), cart.kind(),
				cart.footprint().type(), cart.loop()));
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), add);
		assertEquals(original, document.undo().text());

		AddDynamic looping = new AddDynamic("cart1", "Cart", List.of(new Waypoint("F_5_0", 0),
				new Waypoint("F_5_2", 3.5)), true);
		assertEquals(List.of("+    dynamic cart1 : Cart trajectory [F_5_0 @ 0s, F_5_2 @ 3.5s] loop"),
				Texts.diff(original, document.apply(looping).text()));
	}

	@Test
	void aMovingObjectTheTextCannotSayIsRefused() {
		List<Waypoint> points = List.of(new Waypoint("F_1_1", 0), new Waypoint("F_3_1", 2));
		assertRefused(new AddDynamic("cart1", "Trolley", points, false),
				"No type 'Trolley' in the default catalogue or the imported ones");
		assertRefused(new AddDynamic("table1", "Cart", points, false), "The name 'table1' is taken");
		assertRefused(new AddDynamic("cart1", "Cart", List.of(new Waypoint("F_9_9", 0)), false),
				"no floor or wall named 'F_9_9'");
		assertRefused(new AddDynamic("cart1", "Cart", List.of(), false), "moving object 'cart1' would have none");
		assertThrows(NullPointerException.class, () -> new AddDynamic("cart1", null, points, false));
	}

	@Test
	void thePaletteIsTheDefaultCatalogue() {
		List<PaletteType> palette = document.palette();

		assertEquals(List.of("Floor floor", "Wall wall", "Box object", "Table object", "Chair object",
				"Shelf object", "Bin object", "Cart dynamic", "Human human", "Waffle robot"), palette.stream()
						.map(t -> t.name() + " " + t.category()).toList());
		PaletteType waffle = palette.get(palette.size() - 1);
		assertEquals(List.of("box", 0.281, 0.306), List.of(waffle.shape(), waffle.sizeX(), waffle.sizeY()));
		assertTrue(palette.stream().allMatch(t -> t.colour() != null && t.colour().startsWith("#")), palette::toString);
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

	/** Xtext would re-write the whole room for a change of an element it has no text of: applied one by one. */
	@Test
	void aBatchThatAddsAnElementAndChangesItWritesOnlyTheNewStatement() {
		List<EditOperation> batch = List.of(new AddObject("chair1", "Chair", "F_2_2"), new RotateObject("chair1", 90),
				new AddHuman("visitor", null, List.of(new Waypoint("F_0_1", 0)), false),
				new SetTrajectory("visitor", List.of(new Waypoint("F_0_1", 0), new Waypoint("F_0_2", 3)), true));
		EditResult result = document.apply(batch);

		assertEquals(List.of("+    object chair1 : Chair on F_2_2 yaw 90",
				"+    human visitor trajectory [F_0_1 @ 0s, F_0_2 @ 3s] loop"), Texts.diff(original, result.text()));
		assertEquals(1, result.edits().size());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), batch.toArray(EditOperation[]::new));
		assertEquals(original, document.undo().text());
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
