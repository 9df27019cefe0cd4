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

import org.eclipse.emf.common.util.URI;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.dsl.edit.EditOperation.DeleteObject;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.RemoveFloor;
import org.rei.dsl.edit.EditOperation.RotateObject;
import org.rei.dsl.edit.EditOperation.SetRoute;
import org.rei.dsl.edit.EditOperation.SetTrajectory;
import org.rei.dsl.edit.EditOperation.Stop;
import org.rei.dsl.edit.EditOperation.Waypoint;
import org.rei.dsl.edit.diagram.Diagram;
import org.rei.dsl.validation.ReiIssueCodes;

/**
 * A room with a crowd and a group (examples/people/crowds.rei): the room editor keeps their lines as written when
 * it saves another edit, draws neither as objects nor movers and refuses what only the text can say about them.
 */
class CrowdEditTest {

	private static final String EXAMPLE = "examples/people/crowds.rei";

	@Test
	void movingSomethingElseAndSavingKeepsTheCrowdAndGroupLinesAsWritten(@TempDir Path folder) throws IOException {
		Path file = folder.resolve("crowds.rei");
		Files.copy(Texts.repository().resolve(EXAMPLE), file);
		String original = Files.readString(file);
		RoomDocument document = RoomDocument.open(file);
		assertEquals(List.of(), document.issues());

		EditResult result = document.apply(new MoveObject("table1", "F_9_7"), new RotateObject("shelf1", 90));
		document.save();

		String saved = Files.readString(file);
		assertEquals(result.text(), saved);
		assertEquals(List.of("-    object shelf1 : Shelf on F_3_7", "-    object table1 : Table on F_10_0",
				"+    object shelf1 : Shelf on F_3_7 yaw 90", "+    object table1 : Table on F_9_7"),
				Texts.diff(original, saved));
		assertTrue(saved.contains("""
				    crowd shoppers 12 from [F_0_2, F_0_3, F_0_4, F_0_5, F_1_2, F_1_3, F_1_4, F_1_5]
				                      to [F_12_2, F_12_3, F_12_4, F_12_5, F_13_2, F_13_3, F_13_4, F_13_5]
				      rate 1 speed 1.0 to 1.4 loop
				    group family 3 route [F_5_1, F_5_6 wait 2s] speed 1.0 to 1.2 loop
				"""), saved);
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(original, document.uri(), saved, new MoveObject("table1", "F_9_7"),
				new RotateObject("shelf1", 90));
	}

	/** Every option, in an order of the writer's own and oddly spaced: all of it survives an edit beside it. */
	@Test
	void aCrowdWrittenInAnyOrderSurvivesAnEditBesideIt() {
		String text = """
				testcase T {
				  room R size 8 x 4 {
				    object crate : Box on F_3_0
				    crowd c 2 : Human from [F_0_0,F_0_1]  to [ F_7_0 ] scared once start 2 s speed 0.9 to 1.1  rate 0.5
				    group g 2 route [F_4_2 wait 1 s, F_6_2]  blocks
				    robot r : Waffle on F_4_0
				  }
				  mission M { goto F_5_1 goto F_1_3 }
				}
				""";
		RoomDocument document = RoomDocument.of(URI.createFileURI(Texts.repository().resolve("examples/t.rei")
				.toString()), text);
		assertEquals(List.of(), document.issues());
		EditResult result = document.apply(new MoveObject("crate", "F_2_3"));

		assertEquals(List.of("-    object crate : Box on F_3_0", "+    object crate : Box on F_2_3"),
				Texts.diff(text, result.text()));
		Texts.assertReadsBackAsEdited(text, document.uri(), result.text(), new MoveObject("crate", "F_2_3"));
	}

	/** Their people are not drawn one by one: a crowd's areas and a group's route are (CrowdAreaEditTest). */
	@Test
	void crowdsAndGroupsAreNeitherObjectsNorMovers() {
		Diagram diagram = Texts.open(EXAMPLE).diagram();

		assertEquals(List.of("shelf1", "table1"), diagram.objects().stream().map(Diagram.Item::name).toList());
		assertEquals(List.of(), diagram.movers());
		assertEquals("tb3", diagram.robot().name());
	}

	@Test
	void whatOnlyTheTextCanSayAboutThemIsRefused() {
		RoomDocument document = Texts.open(EXAMPLE);
		String original = document.text();

		assertRefused(document, new MoveObject("shoppers", "F_6_6"),
				"'shoppers' is a crowd of 12 and cannot be moved in the diagram: change its line in the text");
		assertRefused(document, new RotateObject("family", 90),
				"'family' is a group of 3 and cannot be turned in the diagram");
		assertRefused(document, new SetTrajectory("shoppers", List.of(new Waypoint("F_6_6", 0),
				new Waypoint("F_6_5", 4)), false), "'shoppers' is a crowd of 12 and cannot be given a trajectory");
		assertRefused(document, new SetRoute("family", List.of(new Stop("F_5_1", 0), new Stop("F_8_6", 0)), 1.2, 0,
				true, "avoids"), "'family' is a group of 3 and cannot be re-routed");
		assertRefused(document, new MoveObject("table1", "F_9_7"), new MoveObject("family", "F_9_6"),
				"'family' is a group of 3 and cannot be moved");
		assertEquals(original, document.text());
	}

	@Test
	void aFloorACrowdNamesCannotBeRemoved() {
		RoomDocument document = RoomDocument.of(URI.createFileURI(Texts.repository().resolve("examples/g.rei")
				.toString()), """
						testcase G {
						  room R {
						    floor A right B
						    floor B right C
						    floor C
						    robot r : Waffle on A
						    crowd c 1 from [B] to [C]
						  }
						  mission M { goto B goto A }
						}
						""");

		assertRefused(document, new RemoveFloor("C"), "Floor C is still used by crowd 'c'");
	}

	@Test
	void aCrowdOrGroupIsDeletedWithItsLines() {
		RoomDocument document = Texts.open(EXAMPLE);
		String original = document.text();
		EditResult result = document.apply(new DeleteObject("shoppers"), new DeleteObject("family"));

		assertEquals(List.of(
				"-    crowd shoppers 12 from [F_0_2, F_0_3, F_0_4, F_0_5, F_1_2, F_1_3, F_1_4, F_1_5]",
				"-                      to [F_12_2, F_12_3, F_12_4, F_12_5, F_13_2, F_13_3, F_13_4, F_13_5]",
				"-      rate 1 speed 1.0 to 1.4 loop",
				"-    group family 3 route [F_5_1, F_5_6 wait 2s] speed 1.0 to 1.2 loop"),
				Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
	}

	/** PlacementValidator: furniture moved onto a crowd's from floor is an error on the crowd, where it names it. */
	@Test
	void furnitureMovedOntoACrowdsFloorIsAnErrorOnTheCrowd() {
		RoomDocument document = Texts.open(EXAMPLE);
		EditResult result = document.apply(new MoveObject("table1", "F_1_3"));

		assertEquals(1, result.issues().size(), () -> result.issues().toString());
		ValidationIssue issue = result.issues().get(0);
		assertEquals(ReiIssueCodes.FLOOR_OCCUPIED, issue.code());
		assertEquals("crowd", issue.kind());
		assertEquals("shoppers", issue.element());
		assertEquals(11, issue.line());
		assertEquals(64, issue.column());
		assertTrue(issue.message().contains("Floor F_1_3 is already taken by 'table1'"), issue.message());
	}

	/**
	 * A route's speed is written or not (a person without one walks at its type's speed): set to 1.2, it stays
	 * written, since deleting it would hand the person to its type.
	 */
	@Test
	void aRouteSpeedSetTo12StaysWritten() {
		String text = """
				testcase T {
				  room R size 8 x 4 {
				    human ann route [F_3_3, F_3_0] speed 0.9 loop
				    robot r : Waffle on F_4_0
				  }
				  mission M { goto F_5_1 goto F_1_3 }
				}
				""";
		RoomDocument document = RoomDocument.of(URI.createFileURI(Texts.repository().resolve("examples/t.rei")
				.toString()), text);
		SetRoute set = new SetRoute("ann", List.of(new Stop("F_3_3", 0), new Stop("F_3_0", 0)), 1.2, 0, true,
				"avoids");
		EditResult result = document.apply(set);

		assertEquals(List.of("-    human ann route [F_3_3, F_3_0] speed 0.9 loop",
				"+    human ann route [F_3_3, F_3_0] speed 1.2 loop"), Texts.diff(text, result.text()));
		Texts.assertReadsBackAsEdited(text, document.uri(), result.text(), set);
	}

	private static void assertRefused(RoomDocument document, EditOperation operation, String message) {
		assertRefused(document, operation, null, message);
	}

	private static void assertRefused(RoomDocument document, EditOperation first, EditOperation second,
			String message) {
		EditRefusedException refused = assertThrows(EditRefusedException.class,
				() -> document.apply(second == null ? List.of(first) : List.of(first, second)));
		assertTrue(refused.getMessage().contains(message), refused.getMessage());
	}
}
