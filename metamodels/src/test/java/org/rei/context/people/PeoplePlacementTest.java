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
			points.add(String.format(Locale.ROOT, "%s (%.1f, %.1f)", spot.floor().getName(), spot.x(), spot.y()));
		}
		return points;
	}

	@Test
	void aRectangleOfFloorsHoldsALatticeFromItsBottomLeftRowByRow() {
		grid(6, 4);
		List<Floor> area = List.of(grid[1][1], grid[2][1], grid[1][2], grid[2][2]);

		assertEquals(List.of("F_1_1 (1.3, 1.3)", "F_1_1 (1.9, 1.3)", "F_2_1 (2.5, 1.3)", "F_1_1 (1.3, 1.9)",
				"F_1_1 (1.9, 1.9)", "F_2_1 (2.5, 1.9)", "F_1_2 (1.3, 2.5)", "F_1_2 (1.9, 2.5)", "F_2_2 (2.5, 2.5)"),
				points(placement().lattice(area, 0.25)));
	}

	/** A point whose disc would leave the floors is dropped: an L holds less than its bounding square. */
	@Test
	void aPointIsKeptOnlyWhenItsDiscIsOnTheFloors() {
		grid(4, 4);
		List<Floor> corner = List.of(grid[0][0], grid[1][0], grid[0][1]);

		assertEquals(List.of("F_0_0 (0.3, 0.3)", "F_0_0 (0.9, 0.3)", "F_1_0 (1.5, 0.3)", "F_0_0 (0.3, 0.9)",
				"F_0_1 (0.3, 1.5)"), points(placement().lattice(corner, 0.25)));
		assertEquals(List.of("F_3_3 (3.3, 3.3)"), points(placement().lattice(List.of(grid[3][3]), 0.25)));
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

		assertEquals(List.of("A (0.3, 0.3)", "B (1.5, 0.3)", "A (0.3, 0.9)", "B (1.5, 0.9)", "C (0.3, 1.5)",
				"C (0.9, 1.5)", "D (1.5, 1.5)"), points(placement().lattice(List.of(a, b, c, d), 0.25)));
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

		assertEquals(List.of("F_1_0 (1.3, 0.3)", "F_1_0 (1.3, 0.9)", "F_1_1 (1.3, 1.5)"),
				points(placement().from(crowd)));
		assertEquals(List.of("F_5_1 (5.3, 1.3)"), points(placement().to(crowd)));
		crowd.setType(big);
		assertEquals(0.15, placement().radius(crowd));
		assertEquals(List.of("F_5_1 (5.2, 1.2)", "F_5_1 (5.6, 1.2)", "F_5_1 (5.2, 1.6)", "F_5_1 (5.6, 1.6)"),
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
		assertEquals(List.of("F_2_1 (2.5, 1.9)", "F_1_2 (1.9, 2.5)", "F_3_2 (3.1, 2.5)", "F_2_3 (2.5, 3.1)",
				"F_2_1 (2.5, 1.3)", "F_1_2 (1.3, 2.5)", "F_3_2 (3.7, 2.5)", "F_2_3 (2.5, 3.7)"), cross);

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
		assertEquals(List.of("F_3_2 (3.5, 2.3)", "F_2_3 (2.3, 3.5)"), points(placement().beside(family)),
				"the table's floor and the crowd's to floor are not free");

		Group friends = group("friends", 2, grid[3][3]);
		assertEquals(List.of("F_4_3 (4.5, 3.3)", "F_3_4 (3.3, 4.5)"), points(placement().beside(friends)),
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
