/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * What {@code hello} answered: the run, the robot and (with {@code --sut-map}) the static map.
 *
 * @param map walls and furniture, or null unless the run offers the map
 */
public record Session(int protocol, String runId, Clock clock, double controlRate, double deadline, Pose start,
		Robot robot, int goals, StaticMap map) {

	/** hello's robot.drive values, the default first (contract/vocabulary.json drives). */
	public static final List<String> DRIVES = List.of("differential", "holonomic");

	/** lockstep: the simulation waits for every command; realtime: it runs at wall-clock speed. */
	public enum Clock {
		LOCKSTEP, REALTIME
	}

	/**
	 * The robot: footprint sizes (m), velocity limits (m/s, rad/s), laser, its drive ("differential" or
	 * "holonomic"), its sideways speed limit (m/s; 0 for a differential drive) and its outline on the floor (null
	 * from a simulation that sends none).
	 */
	public record Robot(String name, double sizeX, double sizeY, double maxLinear, double maxAngular, Lidar lidar,
			String drive, double maxLateral, Outline outline) {

		/** A differential robot. */
		public Robot(String name, double sizeX, double sizeY, double maxLinear, double maxAngular, Lidar lidar) {
			this(name, sizeX, sizeY, maxLinear, maxAngular, lidar, DRIVES.get(0), 0.0, null);
		}

		public boolean holonomic() {
			return DRIVES.get(1).equals(drive);
		}
	}

	/**
	 * The robot's outline on the floor in its own frame (x forward, y left, m, about its pose): a convex polygon,
	 * counter-clockwise ({@code points} as {x, y} pairs; {@code radius} 0), or a circle of {@code radius} about
	 * ({@code x}, {@code y}) ({@code points} empty).
	 */
	public record Outline(List<double[]> points, double x, double y, double radius) {

		/** hello's robot.outline.type values (contract/vocabulary.json footprints). */
		public static final List<String> TYPES = List.of("polygon", "circle");

		public boolean circle() {
			return radius > 0;
		}
	}

	/**
	 * The laser: beams per scan, ranges (m), scans per second, and where it sits on the robot ({@code x}, {@code y}
	 * in the robot's frame, m; {@code yaw}, rad, the direction of a scan's angle 0): 0 for a box robot.
	 */
	public record Lidar(int beams, double rangeMin, double rangeMax, double rate, double x, double y, double yaw) {

		public Lidar(int beams, double rangeMin, double rangeMax, double rate) {
			this(beams, rangeMin, rangeMax, rate, 0, 0, 0);
		}
	}

	/**
	 * Walls and furniture (never humans) inside the floors' bounds.
	 *
	 * @param occupancy in a room from an occupancy map, the test case's copy of the map ({@code map.yaml}, ROS
	 *                  map_server format) named relative to the case folder ({@link #occupancyPath()}); else null
	 */
	public record StaticMap(double xmin, double ymin, double xmax, double ymax, List<Obstacle> obstacles,
			String occupancy) {

		/** A map of rectangles only, not from an occupancy map. */
		public StaticMap(double xmin, double ymin, double xmax, double ymax, List<Obstacle> obstacles) {
			this(xmin, ymin, xmax, ymax, obstacles, null);
		}

		/**
		 * {@link #occupancy} in the case folder {@code REI_CASE_DIR} (which REI sets for a SUT it starts and writes
		 * to OUT/sut.env), or null without an occupancy map; as the Python kit, the name as it is when the variable
		 * is unset or empty.
		 */
		public Path occupancyPath() {
			return occupancyPath(System.getenv());
		}

		/** {@link #occupancy} in {@code caseDir}, the run's case folder; the name as it is when that is null. */
		public Path occupancyPath(Path caseDir) {
			if (occupancy == null) {
				return null;
			}
			return caseDir == null ? Path.of(occupancy) : caseDir.resolve(occupancy);
		}

		/** {@link #occupancyPath(Path)} with the case folder of {@code env}'s {@code REI_CASE_DIR}. */
		Path occupancyPath(Map<String, String> env) {
			String caseDir = env.get(SutClient.ENV_CASE_DIR);
			return occupancyPath(caseDir == null || caseDir.isEmpty() ? null : Path.of(caseDir));
		}
	}

	/** An oriented rectangle: centre, yaw and full sizes. */
	public record Obstacle(double x, double y, double yaw, double sizeX, double sizeY) {
	}
}
