/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

/** The geometric thresholds as a fact, so that queries read them as data (monitor.json {@code thresholds}). */
public final class Thresholds {

	private final double close;
	private final double collision;

	public Thresholds(double close, double collision) {
		if (!(collision >= 0) || !(close > collision)) {
			throw new IllegalArgumentException("need 0 <= collision < close, got " + collision + ", " + close);
		}
		this.close = close;
		this.collision = collision;
	}

	public double getClose() {
		return close;
	}

	public double getCollision() {
		return collision;
	}
}
