/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/** A planar velocity: forward speed {@code v} (m/s), turn rate {@code w} (rad/s), sideways speed {@code vy} (m/s). */
public record Twist(double v, double w, double vy) {

	/** A differential robot's twist: no sideways speed. */
	public Twist(double v, double w) {
		this(v, w, 0.0);
	}
}
