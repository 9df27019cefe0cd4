/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.layout;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.HashSet;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rei.catalogue.CatalogueFactory;
import org.rei.catalogue.ObjectType;
import org.rei.context.ContextFactory;
import org.rei.context.ContextPackage;
import org.rei.context.Direction;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Robot;
import org.rei.context.Wall;

class FloorLayoutTest {

	private static final ContextFactory F = ContextFactory.eINSTANCE;
	private final Environment env = F.createEnvironment();

	private Floor floor(String name) {
		Floor floor = F.createFloor();
		floor.setName(name);
		env.getOwnedBlocks().add(floor);
		return floor;
	}

	private Wall wall(String name) {
		Wall wall = F.createWall();
		wall.setName(name);
		env.getOwnedBlocks().add(wall);
		return wall;
	}

	/** A columns x rows grid; each floor declares only its right and top neighbours. */
	private Floor[][] grid(int columns, int rows) {
		Floor[][] g = new Floor[columns][rows];
		for (int x = 0; x < columns; x++) {
			for (int y = 0; y < rows; y++) {
				g[x][y] = floor("F_" + x + "_" + y);
			}
		}
		for (int x = 0; x < columns; x++) {
			for (int y = 0; y < rows; y++) {
				if (x + 1 < columns) {
					g[x][y].setRight(g[x + 1][y]);
				}
				if (y + 1 < rows) {
					g[x][y].setTop(g[x][y + 1]);
				}
			}
		}
		return g;
	}

	private static List<String> codes(FloorLayout layout) {
		return layout.problems().stream().map(LayoutProblem::code).toList();
	}

	@Test
	void rectangleStartingInTheMiddleIsShiftedToTheOrigin() {
		env.setFloorSize(2.0);
		Floor[][] g = grid(3, 2);
		Robot robot = F.createRobot();
		robot.setFloor(g[1][1]);
		env.setOwnedRobot(robot);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(), layout.problems());
		assertSame(g[1][1], layout.start().orElseThrow());
		assertEquals(3, layout.columns());
		assertEquals(2, layout.rows());
		for (int x = 0; x < 3; x++) {
			for (int y = 0; y < 2; y++) {
				assertEquals(new Cell(x, y), layout.cellOf(g[x][y]).orElseThrow());
			}
		}
		assertArrayEquals(new double[] { 5.0, 3.0 }, layout.centreOf(g[2][1]), 1e-12);
		assertEquals(List.of(g[0][0], g[0][1], g[1][0], g[1][1], g[2][0], g[2][1]), List.copyOf(layout.cells().keySet()));
	}

	@Test
	void wallsStandCentredOnTheEdgeAndOverlapAtCorners() {
		Floor[][] g = grid(2, 1);
		Wall bottom = wall("W_bottom");
		Wall left = wall("W_left");
		g[0][0].setBottom(bottom);
		g[0][0].setLeft(left);
		ObjectType thick = CatalogueFactory.eINSTANCE.createObjectType();
		thick.setSizeY(0.2);
		thick.setSizeZ(2.5);
		left.setType(thick);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(), layout.problems());
		WallPlacement b = layout.placementOf(bottom).orElseThrow();
		assertEquals(Direction.BOTTOM, b.side());
		assertEquals("Wall", b.type().getName());
		assertArrayEquals(new double[] { 0.5, 0.0, 0.5, 1.1, 0.1, 1.0 },
				new double[] { b.x(), b.y(), b.z(), b.sizeX(), b.sizeY(), b.sizeZ() }, 1e-12);
		WallPlacement l = layout.placementOf(left).orElseThrow();
		assertArrayEquals(new double[] { 0.0, 0.5, 1.25, 0.2, 1.2, 2.5 },
				new double[] { l.x(), l.y(), l.z(), l.sizeX(), l.sizeY(), l.sizeZ() }, 1e-12);
		assertEquals(List.of(bottom, left), layout.walls().stream().map(WallPlacement::wall).toList());
	}

	@Test
	void lShapedRoom() {
		Floor a = floor("A");
		Floor b = floor("B");
		Floor c = floor("C");
		Floor d = floor("D");
		Floor e = floor("E");
		a.setRight(b);
		b.setRight(c);
		a.setTop(d);
		e.setBottom(d);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(), layout.problems());
		assertEquals(3, layout.columns());
		assertEquals(3, layout.rows());
		assertEquals(new Cell(2, 0), layout.cellOf(c).orElseThrow());
		assertEquals(new Cell(0, 2), layout.cellOf(e).orElseThrow());
	}

	@Test
	void ringAroundAMissingCell() {
		Floor[] ring = new Floor[8];
		for (int i = 0; i < 8; i++) {
			ring[i] = floor("R" + i);
		}
		// clockwise from the bottom-left corner: up, up, right, right, down, down, left, (left closes the ring)
		ring[0].setTop(ring[1]);
		ring[1].setTop(ring[2]);
		ring[2].setRight(ring[3]);
		ring[3].setRight(ring[4]);
		ring[4].setBottom(ring[5]);
		ring[5].setBottom(ring[6]);
		ring[6].setLeft(ring[7]);
		ring[7].setLeft(ring[0]);
		ring[1].setRight(wall("h1"));
		ring[3].setBottom(wall("h2"));
		ring[5].setLeft(wall("h3"));
		ring[7].setTop(wall("h4"));

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(), layout.problems());
		assertEquals(List.of("1.0,1.5", "1.5,2.0", "2.0,1.5", "1.5,1.0"),
				layout.walls().stream().map(w -> w.x() + "," + w.y()).toList());
		assertEquals(8, new HashSet<>(layout.cells().values()).size());
		assertFalse(layout.cells().containsValue(new Cell(1, 1)));
		assertEquals(new Cell(2, 2), layout.cellOf(ring[4]).orElseThrow());
		assertEquals(new Cell(1, 0), layout.cellOf(ring[7]).orElseThrow());
	}

	@Test
	void inconsistentLoopIsReportedOnTheReference() {
		Floor a = floor("A");
		Floor b = floor("B");
		a.setRight(b);
		b.setRight(a);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(LayoutIssueCodes.INCONSISTENT_LOOP), codes(layout));
		LayoutProblem problem = layout.problems().get(0);
		assertSame(ContextPackage.Literals.FLOOR__RIGHT, problem.feature());
		assertTrue(problem.element() == a || problem.element() == b);
	}

	@Test
	void twoFloorsOnOneCell() {
		Floor a = floor("A");
		Floor b = floor("B");
		Floor c = floor("C");
		a.setRight(b);
		c.setLeft(a);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(LayoutIssueCodes.OVERLAP), codes(layout));
		assertSame(c, layout.problems().get(0).element());
		assertEquals(layout.cellOf(b), layout.cellOf(c));
	}

	@Test
	void floorNotConnectedToTheRobotsFloor() {
		Floor a = floor("A");
		Floor b = floor("B");
		Floor island = floor("island");
		a.setRight(b);
		Robot robot = F.createRobot();
		robot.setFloor(island);
		env.setOwnedRobot(robot);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(LayoutIssueCodes.DISCONNECTED, LayoutIssueCodes.DISCONNECTED), codes(layout));
		assertEquals(List.of(a, b), layout.problems().stream().map(LayoutProblem::element).toList());
		assertEquals(new Cell(0, 0), layout.cellOf(island).orElseThrow());
		assertTrue(layout.cellOf(a).isEmpty());
		assertThrows(IllegalArgumentException.class, () -> layout.centreOf(a));
	}

	@Test
	void wallNamedByTwoFloorsInTwoPlaces() {
		Floor a = floor("A");
		Floor b = floor("B");
		Wall w = wall("W");
		a.setRight(b);
		a.setTop(w);
		b.setTop(w);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(LayoutIssueCodes.WALL_CONFLICT), codes(layout));
		LayoutProblem problem = layout.problems().get(0);
		assertSame(b, problem.element());
		assertSame(ContextPackage.Literals.FLOOR__TOP, problem.feature());
		assertSame(a, layout.placementOf(w).orElseThrow().floor());
	}

	@Test
	void wallNamedFromBothSidesOfOneEdgeIsOneWall() {
		Floor[][] g = grid(2, 2);
		Wall w = wall("W");
		g[0][0].setRight(w); // the bottom row is joined only through the top row
		g[1][0].setLeft(w);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(), layout.problems());
		assertEquals(new Cell(1, 0), layout.cellOf(g[1][0]).orElseThrow());
		WallPlacement p = layout.placementOf(w).orElseThrow();
		assertSame(g[0][0], p.floor());
		assertEquals(1.0, p.x(), 1e-12);
		assertEquals(0.5, p.y(), 1e-12);
	}

	@Test
	void symmetricDeclarationsAgree() {
		Floor a = floor("A");
		Floor b = floor("B");
		a.setRight(b);
		b.setLeft(a);

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(), layout.problems());
		assertEquals(new Cell(1, 0), layout.cellOf(b).orElseThrow());
	}

	@Test
	void oneSidedDeclarationInfersTheOtherNeighbour() {
		Floor a = floor("A");
		Floor b = floor("B");
		a.setTop(b);

		FloorLayout layout = FloorLayout.compute(env);

		assertSame(a, layout.neighbour(b, Direction.BOTTOM));
		assertSame(b, layout.neighbour(a, Direction.TOP));
		assertNull(layout.neighbour(a, Direction.LEFT));
		assertEquals(new Cell(0, 1), layout.cellOf(b).orElseThrow());
	}

	@Test
	void wallNoFloorNamesHasNoPlace() {
		floor("A");
		Wall w = wall("W");

		FloorLayout layout = FloorLayout.compute(env);

		assertEquals(List.of(LayoutIssueCodes.ORPHAN_WALL), codes(layout));
		assertSame(w, layout.problems().get(0).element());
		assertTrue(layout.walls().isEmpty());
	}

	@Test
	void emptyEnvironmentHasNoCells() {
		FloorLayout layout = FloorLayout.compute(env);

		assertTrue(layout.isValid());
		assertTrue(layout.start().isEmpty());
		assertEquals(0, layout.columns());
	}

	@Test
	void tenThousandFloorsInLinearTime() {
		Floor[][] g = grid(100, 100);
		assertTimeoutPreemptively(Duration.ofSeconds(2), () -> {
			FloorLayout layout = FloorLayout.compute(env);
			assertTrue(layout.isValid());
			assertEquals(10_000, new HashSet<>(layout.cells().values()).size());
			assertEquals(new Cell(99, 42), layout.cellOf(g[99][42]).orElseThrow());
		});
	}
}
