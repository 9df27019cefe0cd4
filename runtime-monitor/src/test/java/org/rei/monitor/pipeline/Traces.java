/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import java.util.ArrayList;
import java.util.List;

import org.rei.monitor.wire.ObjectState;
import org.rei.monitor.wire.RobotState;
import org.rei.monitor.wire.StateMessage;

/**
 * Scripted state streams in the test room at 20 Hz (the collector's default): the robot's true pose as a
 * function of time, an optional human, the laser minimum as the simulator would measure it for a wall ahead.
 * The same scripts exist in Python (src/test/resources/write_trace.py) to prove the wire is the same.
 */
final class Traces {

	static final double DT = 0.05;
	static final double HALF_X = 0.281 / 2;

	private Traces() {
	}

	/**
	 * Drives at 0.2 m/s (+x) from x = 4 toward the east wall (inner face x = 6), stops against it at t = 10 s,
	 * backs off at 0.15 m/s until t = 14 s. Laser minimum = the distance from the centre to the wall.
	 */
	static List<StateMessage> wallApproach() {
		List<StateMessage> out = new ArrayList<>();
		double stop = 6.0 - HALF_X;
		for (int k = 0; k <= 280; k++) {
			double t = k * DT;
			double x = t <= 10 ? Math.min(4.0 + 0.2 * t, stop) : stop - 0.15 * (t - 10);
			double vx = t <= 10 ? (x < stop ? 0.2 : 0) : -0.15;
			List<String[]> contacts = new ArrayList<>();
			if (6.0 - (x + HALF_X) <= 0) {
				contacts.add(new String[] { "tb3", "wall_east" });
			}
			RobotState r = new RobotState("tb3", x, 1.0, 0, 0, vx, 0, 0, new double[] { x, 1.0, 0 }, 6.0 - x, null,
					"ACTIVE", Double.NaN);
			out.add(new StateMessage(k, t, k == 0, List.of(), r, contacts));
		}
		return out;
	}

	/** Gap between the robot and the wall in {@link #wallApproach()} at time t. */
	static double wallGap(double t) {
		double stop = 6.0 - HALF_X;
		double x = t <= 10 ? Math.min(4.0 + 0.2 * t, stop) : stop - 0.15 * (t - 10);
		return 6.0 - (x + HALF_X);
	}

	/** Robot pose {x, y, yaw} on a counter-clockwise circle of radius 0.95 m around table1 at (1.5, 2.5), from the top. */
	static double[] circlePose(double t) {
		double omega = 0.2 / 0.95;
		double theta = Math.PI / 2 + omega * t;
		return new double[] { 1.5 + 0.95 * Math.cos(theta), 2.5 + 0.95 * Math.sin(theta), theta + Math.PI / 2 };
	}

	/** One lap (0.95 m radius at 0.2 m/s: 29.85 s) around the table. */
	static List<StateMessage> circleAroundTable() {
		List<StateMessage> out = new ArrayList<>();
		for (int k = 0; k * DT <= 2 * Math.PI * 0.95 / 0.2; k++) {
			double t = k * DT;
			double[] p = circlePose(t);
			double yaw = Math.atan2(Math.sin(p[2]), Math.cos(p[2]));
			RobotState r = new RobotState("tb3", p[0], p[1], 0, yaw, 0, 0, 0.2 / 0.95, null, Double.NaN, null, null, Double.NaN);
			out.add(new StateMessage(k, t, false, List.of(), r, List.of()));
		}
		return out;
	}

	/** Robot at (3.0 + 0.2 t, 1.0) heading +x; human h1 walking -y at 1 m/s along x = 4.0 from y = 4 (t = 0). */
	static double[] crossingRobot(double t) {
		return new double[] { 3.0 + 0.2 * t, 1.0, 0 };
	}

	static double[] crossingHuman(double t) {
		return new double[] { 4.0, 4.0 - 1.0 * t };
	}

	static List<StateMessage> humanCrossing() {
		List<StateMessage> out = new ArrayList<>();
		for (int k = 0; k <= 120; k++) {
			double t = k * DT;
			double[] r = crossingRobot(t);
			double[] h = crossingHuman(t);
			RobotState robot = new RobotState("tb3", r[0], r[1], 0, 0, 0.2, 0, 0, null, Double.NaN, null, null, Double.NaN);
			ObjectState human = new ObjectState("h1", "HUMAN", h[0], h[1], 0.85, -Math.PI / 2, 0, -1.0, 0);
			out.add(new StateMessage(k, t, false, List.of(human), robot, null));
		}
		return out;
	}

	/**
	 * The robot drives along y = 3.5 through human h1's place in world.json (3.5, 3.5) while the collector does not
	 * publish h1: full frames every second leave it out, until h1 appears there from {@code appearsAt} on.
	 */
	static List<StateMessage> unpublishedHuman(double appearsAt) {
		List<StateMessage> out = new ArrayList<>();
		for (int k = 0; k <= 200; k++) {
			double t = k * DT;
			RobotState robot = new RobotState("tb3", 2.0 + 0.2 * t, 3.5, 0, 0, 0.2, 0, 0, null, Double.NaN, null, null,
					Double.NaN);
			List<ObjectState> objects = t >= appearsAt
					? List.of(new ObjectState("h1", "HUMAN", 3.5, 3.5, 0.85, 0, 0, 0, 0))
					: List.of();
			out.add(new StateMessage(k, t, k % 20 == 0, objects, robot, List.of()));
		}
		return out;
	}

	/** Human h1's x at time t in {@link #humanBumpsRobotAtWall()}: walks +x along y = 1 to x = 5.6 and back. */
	static double bumpingHumanX(double t) {
		return t <= 4 ? 4.0 + 0.4 * t : 5.6 - 0.4 * (t - 4);
	}

	/**
	 * The robot stands against the east wall (touching it, a contact as the simulator reports it) for 8 s while
	 * human h1 walks up to it, bumps it and walks away: the robot is in COLLISION all along, with the wall.
	 */
	static List<StateMessage> humanBumpsRobotAtWall() {
		List<StateMessage> out = new ArrayList<>();
		double x = 6.0 - HALF_X;
		for (int k = 0; k <= 160; k++) {
			double t = k * DT;
			RobotState robot = new RobotState("tb3", x, 1.0, 0, 0, 0, 0, 0, null, Double.NaN, null, null, Double.NaN);
			double hx = bumpingHumanX(t);
			ObjectState human = new ObjectState("h1", "HUMAN", hx, 1.0, 0.85, 0, t <= 4 ? 0.4 : -0.4, 0, 0);
			List<String[]> contacts = new ArrayList<>();
			contacts.add(new String[] { "tb3", "wall_east" });
			out.add(new StateMessage(k, t, k == 0, List.of(human), robot, contacts));
		}
		return out;
	}

	// ---- an independent oracle: footprint distances from vertex-to-rectangle distances (convex, disjoint) ----

	/** Distance from point (px, py) to a rectangle of half extents (hx, hy) at (cx, cy) turned by yaw. */
	static double pointToRectangle(double px, double py, double cx, double cy, double yaw, double hx, double hy) {
		double c = Math.cos(yaw);
		double s = Math.sin(yaw);
		double u = c * (px - cx) + s * (py - cy);
		double v = -s * (px - cx) + c * (py - cy);
		return Math.hypot(Math.max(Math.abs(u) - hx, 0), Math.max(Math.abs(v) - hy, 0));
	}

	/** Distance between two disjoint rectangles: the least vertex-to-rectangle distance both ways. */
	static double rectangles(double[] a, double ahx, double ahy, double[] b, double bhx, double bhy) {
		return Math.min(vertices(a, ahx, ahy, b, bhx, bhy), vertices(b, bhx, bhy, a, ahx, ahy));
	}

	private static double vertices(double[] a, double ahx, double ahy, double[] b, double bhx, double bhy) {
		double best = Double.POSITIVE_INFINITY;
		double c = Math.cos(a[2]);
		double s = Math.sin(a[2]);
		for (int sx = -1; sx <= 1; sx += 2) {
			for (int sy = -1; sy <= 1; sy += 2) {
				double px = a[0] + c * sx * ahx - s * sy * ahy;
				double py = a[1] + s * sx * ahx + c * sy * ahy;
				best = Math.min(best, pointToRectangle(px, py, b[0], b[1], b[2], bhx, bhy));
			}
		}
		return best;
	}
}
