/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.junit.jupiter.api.Test;
import org.rei.dsl.edit.EditOperation.AddCrowd;
import org.rei.dsl.edit.EditOperation.SetCrowd;
import org.rei.dsl.edit.diagram.Diagram;

/**
 * The room editor's crowd edits (issue #38, "place a crowd area"): a new crowd is one new line, a changed crowd
 * changes only the tokens that differ (its line's layout over several lines kept), and a bad edit is refused with
 * a message that says which floor of which area is wrong. The diagram draws crowds' areas and groups' routes.
 */
class CrowdAreaEditTest {

	private static final String EXAMPLE = "examples/people/crowds.rei";

	private static final String ROOM = """
			testcase T {
			  room R size 8 x 4 {
			    object crate : Box on F_3_0
			    // a crowd written over two lines, with options the edit does not touch
			    crowd c 2 from [F_0_0, F_0_1]
			              to [F_7_0] scared start 2s rate 0.5
			    robot r : Waffle on F_4_0
			  }
			  mission M { goto F_5_1 goto F_1_3 }
			}
			""";

	private static RoomDocument room() {
		return RoomDocument.of(URI.createFileURI(Texts.repository().resolve("examples/t.rei").toString()), ROOM);
	}

	@Test
	void aNewCrowdIsOneNewLineThatValidates() {
		RoomDocument document = room();
		AddCrowd add = new AddCrowd("shoppers", null, 3, List.of("F_1_1", "F_1_2", "F_2_1"), List.of("F_6_3", "F_7_3"),
				1.5);
		EditResult result = document.apply(add);

		assertEquals(List.of("+    crowd shoppers 3 from [F_1_1, F_1_2, F_2_1] to [F_6_3, F_7_3] rate 1.5"),
				Texts.diff(ROOM, result.text()));
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(ROOM, document.uri(), result.text(), add);
	}

	@Test
	void aNewCrowdWithoutRateAndOfATypeWritesThem() {
		RoomDocument document = room();
		AddCrowd add = new AddCrowd("walkers", "Human", 1, List.of("F_2_2"), List.of("F_5_3"), null);
		EditResult result = document.apply(add);

		assertEquals(List.of("+    crowd walkers 1 : Human from [F_2_2] to [F_5_3]"), Texts.diff(ROOM, result.text()));
		Texts.assertReadsBackAsEdited(ROOM, document.uri(), result.text(), add);
	}

	@Test
	void changingACrowdChangesOnlyItsTokensThatDiffer() {
		RoomDocument document = room();
		// one from floor swapped and one added, the to area moved, count and rate changed
		SetCrowd set = new SetCrowd("c", 3, List.of("F_0_1", "F_1_1", "F_0_2"), List.of("F_7_3"), 2.0);
		EditResult result = document.apply(set);

		assertEquals(List.of("-    crowd c 2 from [F_0_0, F_0_1]", "-              to [F_7_0] scared start 2s rate 0.5",
				"+    crowd c 3 from [F_0_1, F_1_1, F_0_2]", "+              to [F_7_3] scared start 2s rate 2"),
				Texts.diff(ROOM, result.text()));
		assertEquals(List.of(), result.issues());
		Texts.assertReadsBackAsEdited(ROOM, document.uri(), result.text(), set);
	}

	/** The page's rectangle drawn elsewhere: every floor of an area replaced, the area smaller. */
	@Test
	void anAreaRedrawnElsewhereAndSmallerKeepsTheLayout() {
		RoomDocument document = room();
		SetCrowd set = new SetCrowd("c", 2, List.of("F_5_3"), List.of("F_7_0", "F_7_1", "F_6_0"), 0.5);
		EditResult result = document.apply(set);

		assertEquals(List.of("-    crowd c 2 from [F_0_0, F_0_1]", "-              to [F_7_0] scared start 2s rate 0.5",
				"+    crowd c 2 from [F_5_3]", "+              to [F_7_0, F_7_1, F_6_0] scared start 2s rate 0.5"),
				Texts.diff(ROOM, result.text()));
		Texts.assertReadsBackAsEdited(ROOM, document.uri(), result.text(), set);
	}

	@Test
	void aRateSetToNullGoesWithItsKeyword() {
		RoomDocument document = room();
		SetCrowd set = new SetCrowd("c", 2, List.of("F_0_0", "F_0_1"), List.of("F_7_0"), null);
		EditResult result = document.apply(set);

		assertEquals(1, Texts.diff(ROOM, result.text()).stream().filter(l -> l.startsWith("+")).count());
		assertTrue(result.text().contains("to [F_7_0] scared start 2s\n") || result.text().contains(
				"to [F_7_0] scared start 2s \n"), result.text());
		assertNull(document.diagram().crowds().get(0).rate());
		Texts.assertReadsBackAsEdited(ROOM, document.uri(), result.text(), set);
	}

	@Test
	void undoBringsTheCrowdBack() {
		RoomDocument document = room();
		document.apply(new SetCrowd("c", 5, List.of("F_1_0", "F_1_1", "F_1_2", "F_1_3", "F_0_3"), List.of("F_6_0"),
				1.0));
		assertEquals(ROOM, document.undo().text());
	}

	@Test
	void badCrowdEditsAreRefusedWithWhereTheyAreWrong() {
		RoomDocument document = room();
		assertRefused(document, new SetCrowd("c", 2, List.of("F_0_0", "F_9_9"), List.of("F_7_0"), null),
				"crowd 'c', from[1]: Room 'R' has no floor or wall named 'F_9_9'");
		assertRefused(document, new AddCrowd("d", null, 2, List.of("F_1_1"), List.of("F_2_2", "nowhere"), null),
				"crowd 'd', to[1]: Room 'R' has no floor or wall named 'nowhere'");
		assertRefused(document, new AddCrowd("d", null, 2, List.of(), List.of("F_2_2"), null),
				"A crowd's from area is written with one floor at least: crowd 'd' would have none");
		assertRefused(document, new SetCrowd("c", 0, List.of("F_0_0"), List.of("F_7_0"), null),
				"A crowd has 1 person at least: crowd 'c' would have 0");
		assertRefused(document, new SetCrowd("c", 2, List.of("F_0_0"), List.of("F_7_0"), 0.0),
				"A crowd's rate is people a second, above 0");
		assertRefused(document, new SetCrowd("c", 2, List.of("F_0_0", "F_0_0"), List.of("F_7_0"), null),
				"crowd 'c', from[1]: floor F_0_0 is in the from area twice");
		assertRefused(document, new SetCrowd("crate", 2, List.of("F_0_0"), List.of("F_7_0"), null),
				"'crate' is not a crowd");
		assertRefused(document, new AddCrowd("crate", null, 2, List.of("F_0_0"), List.of("F_7_0"), null),
				"The name 'crate' is taken");
		assertRefused(document, new AddCrowd("e", "NoSuchType", 2, List.of("F_1_1"), List.of("F_7_0"), null),
				"No type 'NoSuchType'");
		assertEquals(ROOM, document.text());
	}

	/** More people than the from area holds: the edit is made (it is the user's file), the validator says so. */
	@Test
	void moreThanFitIsAValidationErrorOnTheCrowd() {
		RoomDocument document = room();
		EditResult result = document.apply(new SetCrowd("c", 200, List.of("F_0_0"), List.of("F_7_0"), null));

		assertTrue(result.issues().stream().anyMatch(i -> "c".equals(i.element()) && "error".equals(i.severity())),
				() -> result.issues().toString());
	}

	@Test
	void theDiagramDrawsCrowdAreasAndGroupRoutes() {
		Diagram diagram = Texts.open(EXAMPLE).diagram();

		assertEquals(List.of(), diagram.movers());
		Diagram.CrowdAreas crowd = diagram.crowds().get(0);
		assertEquals("shoppers", crowd.name());
		assertEquals(12, crowd.count());
		assertEquals(List.of("F_0_2", "F_0_3", "F_0_4", "F_0_5", "F_1_2", "F_1_3", "F_1_4", "F_1_5"),
				crowd.from().stream().map(Diagram.Area::floor).toList());
		assertEquals("F_12_2", crowd.to().get(0).floor());
		assertEquals(1.0, crowd.rate());
		assertTrue(crowd.loop());
		assertEquals(12.5, crowd.to().get(0).x(), 1e-9);
		Diagram.GroupRoute group = diagram.groups().get(0);
		assertEquals("family", group.name());
		assertEquals(3, group.count());
		assertEquals(List.of("F_5_1", "F_5_6"), group.route().stops().stream().map(Diagram.Stop::floor).toList());
		assertEquals(2.0, group.route().stops().get(1).waitSeconds());
		assertTrue(group.loop());
	}

	private static void assertRefused(RoomDocument document, EditOperation operation, String message) {
		EditRefusedException refused = assertThrows(EditRefusedException.class, () -> document.apply(operation));
		assertTrue(refused.getMessage().contains(message), refused.getMessage());
	}
}
