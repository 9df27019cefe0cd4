/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * A robot read from its description has a footprint that is not centred on its origin: a convex polygon (the
 * TurtleBot3 Burger's body reaches 0.038 m forward and 0.102 m back of its wheel axle) or a circle whose centre is
 * off the origin; placed and turned about the origin, never about the outline's centre.
 */
class RobotOutlineTest {

	private static final double EPS = 1e-9;
	// the Burger's outline without the wheels' bulge: x -0.102 .. 0.038, y -0.07 .. 0.07 (counter-clockwise)
	private static final double[][] BODY = { { -0.102, -0.07 }, { 0.038, -0.07 }, { 0.038, 0.07 }, { -0.102, 0.07 } };

	@Test
	void aPolygonIsMeasuredFromItsOwnEdgesNotACentredBox() {
		Footprint wall = Footprint.place("wall", Shape.rectangle(0.2, 2), 1.0, 0, 0); // its face at x = 0.9
		assertEquals(0.9 - 0.038, FootprintDistance.between(Footprint.place("r", Shape.polygon(BODY), 0, 0, 0), wall),
				EPS);
		// turned half a turn about its origin, the long back faces the wall
		assertEquals(0.9 - 0.102, FootprintDistance.between(
				Footprint.place("r", Shape.polygon(BODY), 0, 0, Math.PI), wall), EPS);
	}

	@Test
	void aPolygonsRadiiAreAboutTheOrigin() {
		Shape body = Shape.polygon(BODY);
		assertEquals(Math.hypot(0.102, 0.07), body.boundingRadius(), EPS);
		assertEquals(0.038, body.inscribedRadius(), EPS); // the nearest edge, the front
		assertEquals(0.14, body.sizeX(), EPS);
	}

	@Test
	void anOffCentreCircleTurnsWithTheRobot() {
		Shape disc = Shape.circle(0.05, 0, 0.1); // centred 5 cm ahead of the origin
		Footprint post = Footprint.place("post", Shape.circle(0.2), 0, 1.0, 0);
		// turned to face the post (+y): the disc's centre at (0, 0.05), 0.95 m from the post's, radii 0.1 and 0.1
		assertEquals(0.95 - 0.2, FootprintDistance.between(Footprint.place("r", disc, 0, 0, Math.PI / 2), post), EPS);
		assertEquals(0.15, disc.boundingRadius(), EPS);
		assertEquals(0.05, disc.inscribedRadius(), EPS);
	}
}
