/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.junit.jupiter.api.Test;
import org.rei.context.Direction;
import org.rei.dsl.edit.EditOperation.AddFloor;
import org.rei.dsl.edit.EditOperation.AddGoal;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.diagram.Diagram;
import org.rei.dsl.edit.diagram.DiagramJson;

/**
 * The room editor's benchmark: a 100 x 100 floor graph written out (10,000 floor statements, 19,800 neighbour
 * references) and the largest grid (200 x 200, 40,000 derived floors). Prints the time to open each and to apply
 * one move; asserts only that a move stays a one-token edit, and generous bounds.
 */
class LargeRoomBenchmarkTest {

	private static final URI URI = org.eclipse.emf.common.util.URI
			.createFileURI(Texts.repository().resolve("examples/large.rei").toString());

	static String floorGraph(int columns, int rows) {
		StringBuilder text = new StringBuilder("// generated: ").append(columns).append(" x ").append(rows)
				.append(" floors written out\ntestcase Large {\n  room Hall {\n");
		for (int y = 0; y < rows; y++) {
			for (int x = 0; x < columns; x++) {
				text.append("    floor F_").append(x).append('_').append(y);
				if (y + 1 < rows) {
					text.append(" top F_").append(x).append('_').append(y + 1);
				}
				if (x + 1 < columns) {
					text.append(" right F_").append(x + 1).append('_').append(y);
				}
				text.append('\n');
			}
		}
		return text.append("    object box1 : Box on F_50_50\n    robot tb3 : Waffle on F_0_0\n  }\n")
				.append("  mission Across {\n    goto F_99_99\n    goto F_0_99\n  }\n}\n").toString();
	}

	static String grid(int columns, int rows) {
		return "testcase Largest {\n  room Hall size " + columns + " x " + rows + " {\n"
				+ "    object box1 : Box on F_50_50\n    robot tb3 : Waffle on F_0_0\n  }\n"
				+ "  mission Across {\n    goto F_199_199\n    goto F_0_199\n  }\n}\n";
	}

	@Test
	void aTenThousandFloorGraph() {
		measure("100 x 100 floor graph", floorGraph(100, 100), 10_000);
	}

	@Test
	void theLargestGrid() {
		measure("200 x 200 grid", grid(200, 200), 40_000);
	}

	private static void measure(String what, String text, int floors) {
		RoomDocument.of(URI, floorGraph(10, 10)).apply(new MoveObject("box1", "F_5_6")); // warm up the classes

		long start = System.nanoTime();
		RoomDocument document = RoomDocument.of(URI, text);
		long load = millis(start);
		RoomDocument.Timings loadParts = document.lastTimings();
		assertEquals(List.of(), document.issues());

		start = System.nanoTime();
		Diagram diagram = document.diagram();
		String json = DiagramJson.write(diagram);
		long draw = millis(start);
		assertEquals(floors, diagram.room().floors().size());

		long[] moves = new long[3];
		RoomDocument.Timings moveParts = null;
		for (int i = 0; i < moves.length; i++) {
			start = System.nanoTime();
			EditResult result = document.apply(new MoveObject("box1", "F_60_" + (60 + i)));
			moves[i] = millis(start);
			moveParts = document.lastTimings();
			assertEquals(1, result.edits().size());
			assertEquals("F_60_" + (60 + i), result.edits().get(0).replacement());
		}
		start = System.nanoTime();
		document.apply(new AddGoal("F_10_10", 1));
		long addGoal = millis(start);
		start = System.nanoTime();
		document.undo();
		long undo = millis(start);
		long addFloor = -1;
		if (diagram.room().form().equals("graph")) {
			int afterLastFloor = document.text().indexOf("\n    object box1");
			start = System.nanoTime();
			EditResult result = document.apply(new AddFloor("Porch", Map.of(Direction.BOTTOM, "F_0_0")));
			addFloor = millis(start);
			assertEquals(List.of(new TextEdit(afterLastFloor, 0, "\n    floor Porch bottom F_0_0")), result.edits());
		}

		System.out.printf("%s (%,d floors, %,d characters):%n", what, floors, text.length());
		System.out.printf("  open %,d ms (parse and link %,d, validate %,d); diagram + JSON %,d ms (%,d characters)%n",
				load, loadParts.parse(), loadParts.validate(), draw, json.length());
		System.out.printf("  MoveObject %,d / %,d / %,d ms; last: serialize %,d, re-parse %,d, validate %,d, "
				+ "compare %,d%n", moves[0], moves[1], moves[2], moveParts.serialize(), moveParts.parse(),
				moveParts.validate(), moveParts.compare());
		System.out.printf("  AddGoal %,d ms; undo %,d ms%s%n", addGoal, undo,
				addFloor < 0 ? "" : String.format("; AddFloor %,d ms", addFloor));
	}

	private static long millis(long start) {
		return (System.nanoTime() - start) / 1_000_000;
	}
}
