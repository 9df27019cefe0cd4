/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.config;

import java.util.List;

/** world.json ({@code rei-world/1}, docs/artifacts.md): the parts the monitor needs. */
public record World(String testcase, String environment, double floorSize, List<FloorCell> floors,
		List<WorldObject> objects, WorldRobot robot) {

	/** A floor with its grid cell and its neighbours' names (a floor, a wall or null) TOP, RIGHT, BOTTOM, LEFT. */
	public record FloorCell(String name, int i, int j, String top, String right, String bottom, String left) {
	}

	/**
	 * A body of the world: {@code size} is {@code [x, y, z]}, {@code pose} {@code [x, y, z, yaw]}; a POLYGON
	 * object's {@code footprint} its polygon about its pose (else null).
	 */
	public record WorldObject(String name, String category, String type, String shape, double[] size, double[] pose,
			String floor, org.rei.monitor.geometry.Shape footprint) {

		/** A body whose footprint its shape and size give (a box, a cylinder, a mesh's bounding box). */
		public WorldObject(String name, String category, String type, String shape, double[] size, double[] pose,
				String floor) {
			this(name, category, type, shape, size, pose, floor, null);
		}

		public boolean isObstacle() {
			return !"FLOOR".equals(category);
		}

		public boolean moves() {
			return "HUMAN".equals(category) || "DYNAMIC".equals(category);
		}
	}

	/** The robot: footprint ({@code footprint} read from its description, else the {@code size} box), start pose,
	 * lidar range limits. */
	public record WorldRobot(String name, String type, String shape, double[] size, double[] pose, String floor,
			double lidarRangeMin, double lidarRangeMax, org.rei.monitor.geometry.Shape footprint) {

		/** A box robot: its footprint is the {@code size} rectangle centred on its pose. */
		public WorldRobot(String name, String type, String shape, double[] size, double[] pose, String floor,
				double lidarRangeMin, double lidarRangeMax) {
			this(name, type, shape, size, pose, floor, lidarRangeMin, lidarRangeMax, null);
		}
	}
}
