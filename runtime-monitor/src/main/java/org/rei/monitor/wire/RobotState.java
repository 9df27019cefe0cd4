/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wire;

/**
 * The robot part of a state message. Optional fields: {@code odom} null, {@code laserMin} and
 * {@code laserClearance} NaN, {@code laserRanges} null and {@code navState} null when absent (the collector's
 * configuration decides).
 */
public record RobotState(String name, double x, double y, double z, double yaw, double vx, double vy, double wz,
		double[] odom, double laserMin, double[] laserRanges, String navState, double laserClearance) {

	public boolean hasLaser() {
		return !Double.isNaN(laserMin);
	}
}
