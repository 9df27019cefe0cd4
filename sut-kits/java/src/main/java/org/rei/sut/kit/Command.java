/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/**
 * The velocity command answering one tick: forward speed {@code v} (m/s) and turn rate {@code w} (rad/s). Values
 * beyond the robot's limits are clamped by the simulation; non-finite values are refused here, where the SUT's
 * stack trace still shows who made them (the simulation would only count a rejection and wait for its deadline).
 */
public record Command(double v, double w) {

	/** Stand still. */
	public static final Command STOP = new Command(0, 0);

	public Command {
		if (!Double.isFinite(v) || !Double.isFinite(w)) {
			throw new IllegalArgumentException("command must be finite: v=" + v + ", w=" + w);
		}
	}

	/** This command with {@code |v|} and {@code |w|} limited to the robot's maxima. */
	public Command clamp(Session.Robot robot) {
		return new Command(clamp(v, robot.maxLinear()), clamp(w, robot.maxAngular()));
	}

	private static double clamp(double value, double limit) {
		return Math.max(-limit, Math.min(limit, value));
	}
}
