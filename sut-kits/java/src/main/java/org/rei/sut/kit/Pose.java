/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/** A planar pose: metres and radians (yaw in [-pi, pi)). */
public record Pose(double x, double y, double yaw) {

	/** Euclidean distance from this pose's position to the point (x, y). */
	public double distanceTo(double px, double py) {
		return Math.hypot(px - x, py - y);
	}

	/** Euclidean distance between the positions of both poses. */
	public double distanceTo(Pose other) {
		return distanceTo(other.x, other.y);
	}

	/** Direction of the point (x, y) relative to this pose's heading, in [-pi, pi): positive is to the left. */
	public double bearingTo(double px, double py) {
		return normalize(Math.atan2(py - y, px - x) - yaw);
	}

	/** The angle a in [-pi, pi). */
	public static double normalize(double a) {
		double r = (a + Math.PI) % (2 * Math.PI);
		return (r < 0 ? r + 2 * Math.PI : r) - Math.PI;
	}
}
