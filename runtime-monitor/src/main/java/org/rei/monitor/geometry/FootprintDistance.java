/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.geometry;

/**
 * Distance between two footprints (not between centres, thesis 6.1.3.1): 0 when they touch or overlap.
 * Polygon distances come from JTS; a circle enters as its centre point minus its radius, which is exact.
 */
public final class FootprintDistance {

	private FootprintDistance() {
	}

	/** Shortest distance in metres between the two footprints, 0 if they intersect. */
	public static double between(Footprint a, Footprint b) {
		if (a.isCircle() && b.isCircle()) {
			return Math.max(0, Math.hypot(a.circleX() - b.circleX(), a.circleY() - b.circleY()) - a.shape().radius()
					- b.shape().radius());
		}
		double d = a.geometry().distance(b.geometry());
		if (a.isCircle()) {
			d -= a.shape().radius();
		}
		if (b.isCircle()) {
			d -= b.shape().radius();
		}
		return Math.max(0, d);
	}
}
