/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/**
 * One planar laser scan in the robot frame. Beam {@code i} points at {@code angleMin + i * angleIncrement}; a beam
 * that hit nothing is {@code +inf}. The array is shared with later ticks (a tick without a new scan repeats the
 * last one): read it, do not modify it.
 */
public record Scan(double t, double angleMin, double angleMax, double angleIncrement, double scanTime,
		double rangeMin, double rangeMax, double[] ranges) {

	/** The direction of beam {@code i} in the robot frame, in [-pi, pi). */
	public double angle(int i) {
		return Pose.normalize(angleMin + i * angleIncrement);
	}

	/**
	 * The shortest range among the beams pointing into the sector [from, to] (radians in the robot frame, within
	 * [-pi, pi), from &lt;= to; 0 is straight ahead), or {@code +inf} if none hit anything.
	 */
	public double minRange(double from, double to) {
		double min = Double.POSITIVE_INFINITY;
		for (int i = 0; i < ranges.length; i++) {
			double a = angle(i);
			if (a >= from && a <= to && ranges[i] >= rangeMin) {
				min = Math.min(min, ranges[i]);
			}
		}
		return min;
	}

	@Override
	public String toString() {
		return "Scan[t=" + t + ", beams=" + ranges.length + "]";
	}
}
