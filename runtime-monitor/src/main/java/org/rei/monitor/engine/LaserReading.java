/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

/**
 * What the laser says about the robot's surroundings: the minimum range (the thesis's min filter, 5.1.6.3)
 * minus the distance from the sensor to the edge of the robot's footprint, so that it compares with the same
 * thresholds as footprint distances. {@code +inf} when no beam hit.
 */
public final class LaserReading {

	private final String robot;
	private final String sensor;
	private double distance;

	public LaserReading(String robot, String sensor, double distance) {
		this.robot = robot;
		this.sensor = sensor;
		this.distance = distance;
	}

	public String getRobot() {
		return robot;
	}

	public String getSensor() {
		return sensor;
	}

	public double getDistance() {
		return distance;
	}

	boolean set(double d) {
		boolean changed = d != distance;
		distance = d;
		return changed;
	}
}
