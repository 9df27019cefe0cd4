/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import java.util.List;

/**
 * What {@code hello} answered: the run, the robot and (with {@code --sut-map}) the static map.
 *
 * @param map walls and furniture, or null unless the run offers the map
 */
public record Session(int protocol, String runId, Clock clock, double controlRate, double deadline, Pose start,
		Robot robot, int goals, StaticMap map) {

	/** lockstep: the simulation waits for every command; realtime: it runs at wall-clock speed. */
	public enum Clock {
		LOCKSTEP, REALTIME
	}

	/** The robot: footprint sizes (m), velocity limits (m/s, rad/s) and laser. */
	public record Robot(String name, double sizeX, double sizeY, double maxLinear, double maxAngular, Lidar lidar) {
	}

	/** The laser: beams per scan, ranges (m), scans per second. */
	public record Lidar(int beams, double rangeMin, double rangeMax, double rate) {
	}

	/** Walls and furniture (never humans) inside the floors' bounds. */
	public record StaticMap(double xmin, double ymin, double xmax, double ymax, List<Obstacle> obstacles) {
	}

	/** An oriented rectangle: centre, yaw and full sizes. */
	public record Obstacle(double x, double y, double yaw, double sizeX, double sizeY) {
	}
}
