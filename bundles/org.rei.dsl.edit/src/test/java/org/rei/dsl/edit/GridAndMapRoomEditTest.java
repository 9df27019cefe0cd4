/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rei.context.Direction;
import org.rei.dsl.edit.EditOperation.AddGoal;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.EditOperation.AddWall;
import org.rei.dsl.edit.EditOperation.DeleteObject;
import org.rei.dsl.edit.EditOperation.MoveGoal;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.RemoveGoal;
import org.rei.dsl.edit.EditOperation.RotateObject;
import org.rei.dsl.edit.EditOperation.SetTrajectory;
import org.rei.dsl.edit.EditOperation.Waypoint;
import org.rei.dsl.edit.diagram.Diagram;

/** Rooms whose floors are derived: a 12 x 8 grid (examples/warehouse.rei), a map (examples/l_shaped_office.rei). */
class GridAndMapRoomEditTest {

	@Test
	void aBatchOnAGridRoomTouchesOnlyItsStatements() {
		RoomDocument document = Texts.open("examples/warehouse.rei");
		String original = document.text();
		List<EditOperation> batch = List.of(new DeleteObject("shelfA2"), new DeleteObject("crate1"),
				new AddObject("shelfA4", "Shelf", "F_6_2"), new MoveObject("bin1", "F_10_4"),
				new SetTrajectory("driver", List.of(new Waypoint("F_11_1", 0), new Waypoint("F_11_6", 15),
						new Waypoint("F_9_7", 22)), true),
				new MoveGoal(3, 0), new RemoveGoal(2), new AddGoal("F_5_5", 3));
		EditResult result = document.apply(batch);

		assertEquals(List.of("-    object shelfA2 : Shelf on F_4_2", "-    object bin1 : Bin on F_10_3",
				"-    object crate1 : Box on F_1_6", "+    object bin1 : Bin on F_10_4",
				"-    human driver trajectory [F_11_1 @ 0s, F_11_6 @ 15s, F_9_7 @ 22s] once",
				"+    human driver trajectory [F_11_1 @ 0s, F_11_6 @ 15s, F_9_7 @ 22s] loop",
				"+    object shelfA4 : Shelf on F_6_2", "+    goto F_0_0", "-    goto F_10_7", "-    goto F_0_0",
				"+    goto F_5_5"), Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		// the derived floors stay derived: no floor statement was written
		assertTrue(!result.text().contains("floor "), result.text());
		assertEquals(96, document.diagram().room().floors().size());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), batch.toArray(EditOperation[]::new));

		assertEquals(original, document.undo().text());
	}

	@Test
	void theDiagramOfAGridRoom() {
		Diagram diagram = Texts.open("examples/simple_navigation.rei").diagram();

		assertEquals("grid", diagram.room().form());
		assertEquals(List.of(6, 4, 24, 20), List.of(diagram.room().columns(), diagram.room().rows(),
				diagram.room().floors().size(), diagram.room().walls().size()));
		Diagram.FloorCell f32 = diagram.room().floors().stream().filter(f -> f.name().equals("F_3_2")).findFirst()
				.orElseThrow();
		assertEquals(List.of(3, 2, 3.5, 2.5, false), List.of(f32.x(), f32.y(), f32.centreX(), f32.centreY(),
				f32.written()));
		Diagram.Item table = diagram.objects().get(0);
		assertEquals(new Diagram.Item("table1", "object", "F_2_1", 0, 2.5, 1.5,
				new Diagram.Footprint("Table", "box", 1.2, 0.8, 0.75, "#8B5A2B")), table);
		assertEquals("tb3", diagram.robot().name());
		assertEquals("Waffle", diagram.robot().footprint().type());
		Diagram.Mover walker = diagram.movers().get(0);
		assertEquals(List.of("human", "cylinder", true), List.of(walker.kind(), walker.footprint().shape(),
				walker.loop()));
		assertEquals(new Diagram.Waypoint("F_3_2", 6, 3.5, 2.5), walker.points().get(1));
		assertEquals(List.of(new Diagram.Goal(0, "F_4_0", null, 4.5, 0.5), new Diagram.Goal(1, "F_5_3", null, 5.5,
				3.5)), diagram.mission().goals());
		assertEquals(120.0, diagram.mission().taskTimeout());
		assertEquals(new Diagram.Monitor(0.25, 0.01, 1), diagram.monitor());
		String json = org.rei.dsl.edit.diagram.DiagramJson.write(diagram);
		assertTrue(json.contains("{\"name\":\"table1\",\"kind\":\"object\",\"floor\":\"F_2_1\",\"yaw\":0.0,\"x\":2.5,"
				+ "\"y\":1.5,\"footprint\":{\"type\":\"Table\",\"shape\":\"box\",\"sizeX\":1.2,\"sizeY\":0.8,"), json);
	}

	@Test
	void aMapRoomKeepsItsDrawingAndRefusesWalls() {
		RoomDocument document = Texts.open("examples/l_shaped_office.rei");
		String original = document.text();

		EditResult result = document.apply(new RotateObject("tb3", 0), new MoveObject("desk", "F_5_1"));

		assertEquals(List.of("-    object desk : Table on F_4_1", "-    robot tb3 : Waffle on F_0_0 yaw 90",
				"+    object desk : Table on F_5_1", "+    robot tb3 : Waffle on F_0_0"),
				Texts.diff(original, result.text()));
		assertEquals(2, result.edits().size());
		EditRefusedException refused = assertThrows(EditRefusedException.class,
				() -> document.apply(new AddWall("W", "F_0_0", Direction.LEFT)));
		assertEquals("Cannot add wall W: room 'Office' derives its floors and walls from its map; change the map, or "
				+ "write the room as a floor graph (floor A right B ...)", refused.getMessage());
		assertEquals(0.8, document.diagram().room().floorSize());
		assertEquals("map", document.diagram().room().form());
	}
}
