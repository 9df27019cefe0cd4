/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Envelope;

class FootprintDistanceTest {

	private static final double EPS = 1e-9;

	private static Footprint box(String name, double sx, double sy, double x, double y, double yawDeg) {
		return Footprint.place(name, Shape.rectangle(sx, sy), x, y, Math.toRadians(yawDeg));
	}

	@Test
	void squareTurnedBy45DegreesMeetsWithItsCorner() {
		// unit square at the origin; unit square at (2, 0) turned 45 deg: its corner reaches x = 2 - sqrt(2)/2
		double expected = 2 - Math.sqrt(2) / 2 - 0.5;
		assertEquals(expected, FootprintDistance.between(box("a", 1, 1, 0, 0, 0), box("b", 1, 1, 2, 0, 45)), EPS);
	}

	@Test
	void rectangleTurnedBy90DegreesSwapsItsExtents() {
		// 2 x 1 at the origin spans y in [-0.5, 0.5]; 2 x 1 at (0, 3) turned 90 deg spans y in [2, 4]
		assertEquals(1.5, FootprintDistance.between(box("a", 2, 1, 0, 0, 0), box("b", 2, 1, 0, 3, 90)), EPS);
	}

	@Test
	void cornersFacingDiagonallyAreApartByTheDiagonal() {
		assertEquals(Math.sqrt(2), FootprintDistance.between(box("a", 1, 1, 0, 0, 0), box("b", 1, 1, 2, 2, 0)), EPS);
	}

	@Test
	void turnedRobotBesideAWall() {
		// robot 0.281 x 0.306 turned 30 deg at (1, 1); wall face at x = 1.5. Corner x offset: the largest of
		// |0.1405 cos30 -+ 0.153 sin30| = 0.1405 * 0.8660254 + 0.153 * 0.5 = 0.1981766
		double corner = 0.1405 * Math.cos(Math.toRadians(30)) + 0.153 * 0.5;
		Footprint robot = box("tb3", 0.281, 0.306, 1, 1, 30);
		Footprint wall = box("wall", 0.1, 4, 1.55, 1, 0);
		assertEquals(0.5 - corner, FootprintDistance.between(robot, wall), EPS);
	}

	@Test
	void circleIsMeasuredFromItsRim() {
		// unit square turned 45 deg: top corner at y = sqrt(2)/2; circle of diameter 0.5 centred at (0, 2)
		Footprint human = Footprint.place("h", Shape.circle(0.5), 0, 2, 0);
		assertEquals(2 - 0.25 - Math.sqrt(2) / 2, FootprintDistance.between(box("a", 1, 1, 0, 0, 45), human), EPS);
		assertEquals(2 - 0.25 - Math.sqrt(2) / 2, FootprintDistance.between(human, box("a", 1, 1, 0, 0, 45)), EPS);
	}

	@Test
	void twoCirclesAreApartByCentresLessRadii() {
		Footprint a = Footprint.place("a", Shape.circle(0.5), 0, 0, 0);
		Footprint b = Footprint.place("b", Shape.circle(1.0), 3, 4, 0);
		assertEquals(5 - 0.25 - 0.5, FootprintDistance.between(a, b), EPS);
	}

	@Test
	void overlappingFootprintsAreAtZero() {
		assertEquals(0, FootprintDistance.between(box("a", 1, 1, 0, 0, 0), box("b", 1, 1, 0.5, 0.5, 10)), 0);
		assertEquals(0, FootprintDistance.between(box("a", 1, 1, 0, 0, 0), Footprint.place("c", Shape.circle(1), 0.9, 0, 0)), 0);
	}

	@Test
	void indexReturnsOnlyObstaclesNearTheQueryArea() {
		ObstacleIndex index = new ObstacleIndex();
		for (int i = 0; i < 100; i++) {
			index.putStatic(box("box" + i, 0.2, 0.2, i, 0, 0));
		}
		index.putMoving(Footprint.place("h1", Shape.circle(0.5), 10.5, 0, 0));
		index.putMoving(Footprint.place("h2", Shape.circle(0.5), 50, 0, 0));
		List<String> names = index.candidates(new Envelope(9.8, 11.2, -0.1, 0.1)).stream().map(Footprint::name)
				.sorted().toList();
		assertEquals(List.of("box10", "box11", "h1"), names);
		index.putMoving(Footprint.place("h2", Shape.circle(0.5), 10.0, 0.2, 0));
		assertEquals(4, index.candidates(new Envelope(9.8, 11.2, -0.1, 0.1)).size());
	}
}
