/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.people;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.junit.jupiter.api.Test;
import org.rei.catalogue.CatalogueFactory;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.Shape;
import org.rei.context.ContextFactory;
import org.rei.context.Crowd;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.Robot;
import org.rei.context.Route;
import org.rei.context.RouteStop;
import org.rei.context.StaticObject;
import org.rei.context.Wall;
import org.rei.context.layout.FloorLayout;

/** The lattice of docs/language.md's "Crowds and groups", on rooms small enough to check by hand. */
class PeoplePlacementTest {

	private static final ContextFactory F = ContextFactory.eINSTANCE;
	private final Environment env = F.createEnvironment();
	private Floor[][] grid;

	/** A columns x rows grid room of 1 m floors, each naming its right and top neighbours, robot at (0, 0). */
	private void grid(int columns, int rows) {
		grid = new Floor[columns][rows];
		for (int x = 0; x < columns; x++) {
			for (int y = 0; y < rows; y++) {
				Floor floor = F.createFloor();
				floor.setName("F_" + x + "_" + y);
				env.getOwnedBlocks().add(floor);
				grid[x][y] = floor;
			}
		}
		for (int x = 0; x < columns; x++) {
			for (int y = 0; y < rows; y++) {
				if (x + 1 < columns) {
					grid[x][y].setRight(grid[x + 1][y]);
				}
				if (y + 1 < rows) {
					grid[x][y].setTop(grid[x][y + 1]);
				}
			}
		}
		Robot robot = F.createRobot();
		robot.setName("r");
		robot.setFloor(grid[0][0]);
		env.setOwnedRobot(robot);
	}

	private PeoplePlacement placement() {
		return PeoplePlacement.of(env, FloorLayout.compute(env), null);
	}

	private static List<String> points(List<PeoplePlacement.Spot> spots) {
		List<String> points = new ArrayList<>();
		for (PeoplePlacement.Spot spot : spots) {
			points.add(String.format(Locale.ROOT, "%s (%.2f, %.2f)", spot.floor().getName(), spot.x(), spot.y()));
		}
		return points;
	}

	@Test
	void aRectangleOfFloorsHoldsALatticeFromItsBottomLeftRowByRow() {
		grid(6, 4);
		List<Floor> area = List.of(grid[1][1], grid[2][1], grid[1][2], grid[2][2]);

		assertEquals(List.of("F_1_1 (1.30, 1.30)", "F_1_1 (1.90, 1.30)", "F_2_1 (2.50, 1.30)",
				"F_1_1 (1.30, 1.90)", "F_1_1 (1.90, 1.90)", "F_2_1 (2.50, 1.90)", "F_1_2 (1.30, 2.50)",
				"F_1_2 (1.90, 2.50)", "F_2_2 (2.50, 2.50)"),
				points(placement().lattice(area, 0.25)));
	}

	/** A point whose disc would leave the floors is dropped: an L holds less than its bounding square. */
	@Test
	void aPointIsKeptOnlyWhenItsDiscIsOnTheFloors() {
		grid(4, 4);
		List<Floor> corner = List.of(grid[0][0], grid[1][0], grid[0][1]);

		assertEquals(List.of("F_0_0 (0.30, 0.30)", "F_0_0 (0.90, 0.30)", "F_1_0 (1.50, 0.30)", "F_0_0 (0.30, 0.90)",
				"F_0_1 (0.30, 1.50)"), points(placement().lattice(corner, 0.25)));
		assertEquals(List.of("F_3_3 (3.30, 3.30)"), points(placement().lattice(List.of(grid[3][3]), 0.25)));
		assertEquals(List.of(), points(placement().lattice(List.of(grid[3][3]), 0.5)), "a 1 m disc needs more");
	}

	/** Two floors side by side with a wall between them (an explicit room): no one stands astride the wall. */
	@Test
	void noPointCrossesAWallBetweenTwoFloorsOfTheArea() {
		Floor a = F.createFloor();
		a.setName("A");
		Floor b = F.createFloor();
		b.setName("B");
		Floor c = F.createFloor();
		c.setName("C");
		Floor d = F.createFloor();
		d.setName("D");
		Wall w = F.createWall();
		w.setName("W");
		env.getOwnedBlocks().addAll(List.of(a, b, c, d, w));
		a.setRight(w); // A | B, joined round through C and D above them
		b.setLeft(w);
		a.setTop(c);
		c.setRight(d);
		d.setBottom(b);
		Robot robot = F.createRobot();
		robot.setFloor(c);
		env.setOwnedRobot(robot);

		assertEquals(List.of("A (0.30, 0.30)", "B (1.50, 0.30)", "A (0.30, 0.90)", "B (1.50, 0.90)",
				"C (0.30, 1.50)", "C (0.90, 1.50)", "D (1.50, 1.50)"),
				points(placement().lattice(List.of(a, b, c, d), 0.25)));
	}

	/**
	 * As the simulation's walkable area leaves them out: a wall stands half on its floor, so the lattice starts at
	 * its inner face, and furniture reaching over from the next floor keeps people off.
	 */
	@Test
	void wallsAndFurnitureKeepPeopleOff() {
		grid(3, 2);
		Wall wall = F.createWall();
		wall.setName("W");
		env.getOwnedBlocks().add(wall);
		grid[0][0].setLeft(wall);
		ObjectType bench = CatalogueFactory.eINSTANCE.createObjectType();
		bench.setName("Bench");
		bench.setCategory(ObjectCategory.STATIC);
		bench.setShape(Shape.BOX);
		bench.setSizeX(1.6);
		bench.setSizeY(0.8);
		StaticObject object = F.createStaticObject();
		object.setName("bench");
		object.setType(bench);
		object.setFloor(grid[2][0]);
		env.getOwnedObjects().add(object);

		assertEquals(List.of("F_0_0 (0.35, 0.30)", "F_0_0 (0.95, 0.30)"),
				points(placement().lattice(List.of(grid[0][0], grid[1][0]), 0.25)),
				"from the wall's face at 0.05; (1.55, 0.30) is 0.15 m from the bench's end at 1.7");
		object.setYaw(90);
		assertEquals(List.of("F_0_0 (0.35, 0.30)", "F_0_0 (0.95, 0.30)", "F_1_0 (1.55, 0.30)"),
				points(placement().lattice(List.of(grid[0][0], grid[1][0]), 0.25)), "turned, it reaches no further");
	}

	@Test
	void aCrowdStartsOnItsFromFloorsAndWalksToItsToFloors() {
		grid(6, 2);
		Crowd crowd = F.createCrowd();
		crowd.setCount(2);
		crowd.getFrom().addAll(List.of(grid[1][0], grid[1][1]));
		crowd.getTo().add(grid[5][1]);
		env.getOwnedObjects().add(crowd);
		ObjectType big = CatalogueFactory.eINSTANCE.createObjectType();
		big.setCategory(ObjectCategory.HUMAN);
		big.setSizeX(0.3);

		assertEquals(List.of("F_1_0 (1.30, 0.30)", "F_1_0 (1.30, 0.90)", "F_1_1 (1.30, 1.50)"),
				points(placement().from(crowd)));
		assertEquals(List.of("F_5_1 (5.30, 1.30)"), points(placement().to(crowd)));
		crowd.setType(big);
		assertEquals(0.15, placement().radius(crowd));
		assertEquals(List.of("F_5_1 (5.20, 1.20)", "F_5_1 (5.60, 1.20)", "F_5_1 (5.20, 1.60)", "F_5_1 (5.60, 1.60)"),
				points(placement().to(crowd)));
	}

	/**
	 * A group's followers stand on the leader's floor and the free floors beside it, nearest the leader first,
	 * never nearer to it than a spacing; a floor with furniture, a start, a crowd's floors or an earlier group's
	 * followers is not free.
	 */
	@Test
	void aGroupsFollowersStandBesideTheLeaderOnFreeFloors() {
		grid(5, 5);
		Group family = group("family", 3, grid[2][2]);
		List<String> cross = points(placement().beside(family));
		assertEquals(List.of("F_2_1 (2.50, 1.90)", "F_1_2 (1.90, 2.50)", "F_3_2 (3.10, 2.50)", "F_2_3 (2.50, 3.10)",
				"F_2_1 (2.50, 1.30)", "F_1_2 (1.30, 2.50)", "F_3_2 (3.70, 2.50)", "F_2_3 (2.50, 3.70)"), cross);

		StaticObject table = F.createStaticObject();
		table.setName("table");
		table.setFloor(grid[2][1]);
		env.getOwnedObjects().add(0, table);
		Crowd crowd = F.createCrowd();
		crowd.setCount(1);
		crowd.getFrom().add(grid[0][4]);
		crowd.getTo().add(grid[1][2]);
		env.getOwnedObjects().add(1, crowd);
		// an L of three floors: the lattice starts at its own corner
		assertEquals(List.of("F_3_2 (3.50, 2.30)", "F_2_3 (2.30, 3.50)"), points(placement().beside(family)),
				"the table's floor and the crowd's to floor are not free");

		Group friends = group("friends", 2, grid[3][3]);
		assertEquals(List.of("F_4_3 (4.50, 3.30)", "F_3_4 (3.30, 4.50)"), points(placement().beside(friends)),
				"family's two followers stand on F_3_2 and F_2_3, which are not free for friends");
	}

	private Group group(String name, int count, Floor start) {
		Group group = F.createGroup();
		group.setName(name);
		group.setCount(count);
		Route route = F.createRoute();
		RouteStop stop = F.createRouteStop();
		stop.setFloor(start);
		route.getOwnedStops().add(stop);
		group.setOwnedRoute(route);
		env.getOwnedObjects().add(group);
		return group;
	}
}
