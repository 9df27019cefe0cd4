/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.junit.jupiter.api.Test;
import org.rei.dsl.edit.EditOperation.AddGoal;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.EditOperation.DeleteObject;
import org.rei.dsl.edit.EditOperation.MoveGoal;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.RotateObject;

/** What happens to comments, odd spacing and line ends next to an edit. */
class LayoutPreservationTest {

	private static final URI URI = org.eclipse.emf.common.util.URI
			.createFileURI(Texts.repository().resolve("examples/commented.rei").toString());

	private static final String TEXT = """
			testcase Commented {
			    room Lab size 4 x 3 {
			        object table1 : Table   on F_2_1 // by the window
			        /* the shelf */ object shelf1 : Shelf on F_0_2
			        // the bin, soon gone
			        object bin1 : Bin on F_3_2
			        robot tb3 : Waffle on F_0_0
			    }
			    mission Round {
			        goto F_3_0 within 60 s
			        // then back up
			        goto F_1_2
			        goto F_3_1
			    }
			}
			""";

	@Test
	void aTokenNextToCommentsAndOddSpacingIsReplacedAlone() {
		RoomDocument document = RoomDocument.of(URI, TEXT);
		EditResult result = document.apply(new MoveObject("table1", "F_1_1"), new RotateObject("table1", 90));

		assertEquals(List.of("-        object table1 : Table   on F_2_1 // by the window",
				"+        object table1 : Table   on F_1_1 yaw 90 // by the window"), Texts.diff(TEXT, result.text()));
	}

	@Test
	void aDeletedStatementTakesTheCommentLinesAboveItAlong() {
		RoomDocument document = RoomDocument.of(URI, TEXT);
		EditResult result = document.apply(new DeleteObject("bin1"));

		assertEquals(List.of("-        // the bin, soon gone", "-        object bin1 : Bin on F_3_2"),
				Texts.diff(TEXT, result.text()));
	}

	@Test
	void aMovedGoalIsWrittenAnewAtItsPlaceWithItsComment() {
		RoomDocument document = RoomDocument.of(URI, TEXT);
		EditResult result = document.apply(new MoveGoal(1, 0));

		assertEquals(TEXT.replace("""
				        goto F_3_0 within 60 s
				        // then back up
				        goto F_1_2
				""", """
				        // then back up
				        goto F_1_2
				        goto F_3_0 within 60 s
				"""), result.text());
		// the goal that stays keeps its spelling ("60 s"): only the moved one is written
		assertEquals(2, result.edits().size());
		assertEquals(List.of(), result.issues());
	}

	@Test
	void twoNewStatementsAtOnePlaceAreWrittenOneAfterTheOther() {
		RoomDocument document = RoomDocument.of(URI, TEXT);
		List<EditOperation> batch = List.of(new AddObject("box1", "Box", "F_1_0"), new AddObject("box2", "Box",
				"F_2_0"), new AddGoal("F_0_1", 3), new AddGoal("F_0_2", 4));
		EditResult result = document.apply(batch);

		assertEquals(List.of("+        object box1 : Box on F_1_0", "+        object box2 : Box on F_2_0",
				"+        goto F_0_1", "+        goto F_0_2"), Texts.diff(TEXT, result.text()));
		assertEquals(1, result.edits().size());
		Texts.assertReadsBackAsEdited(TEXT, URI, result.text(), batch.toArray(EditOperation[]::new));
		assertEquals(TEXT, document.undo().text());
	}

	@Test
	void windowsLineEndsStayWindowsLineEnds() {
		String crlf = TEXT.replace("\n", "\r\n");
		RoomDocument document = RoomDocument.of(URI, crlf);
		EditResult result = document.apply(new AddGoal("F_0_1", 1));

		assertEquals(crlf.replace("        goto F_3_0 within 60 s\r\n",
				"        goto F_3_0 within 60 s\r\n        goto F_0_1\r\n"), result.text());
	}
}
