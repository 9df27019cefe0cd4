/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/**
 * The velocity command answering one tick: forward speed {@code v} (m/s), turn rate {@code w} (rad/s) and, for a
 * holonomic robot, sideways speed {@code vy} (m/s, towards the robot's left). Values
 * beyond the robot's limits are clamped by the simulation; non-finite values are refused here, where the SUT's
 * stack trace still shows who made them (the simulation would only count a rejection and wait for its deadline).
 */
public record Command(double v, double w, double vy) {

	/** Stand still. */
	public static final Command STOP = new Command(0, 0);

	public Command {
		if (!Double.isFinite(v) || !Double.isFinite(w) || !Double.isFinite(vy)) {
			throw new IllegalArgumentException("command must be finite: v=" + v + ", w=" + w + ", vy=" + vy);
		}
	}

	/** Forward speed and turn rate, no sideways speed (all a differential robot takes). */
	public Command(double v, double w) {
		this(v, w, 0.0);
	}

	/** This command with {@code |v|}, {@code |w|} and {@code |vy|} limited to the robot's maxima (a differential
	 * robot's sideways maximum is 0). */
	public Command clamp(Session.Robot robot) {
		return new Command(clamp(v, robot.maxLinear()), clamp(w, robot.maxAngular()), clamp(vy, robot.maxLateral()));
	}

	private static double clamp(double value, double limit) {
		return Math.max(-limit, Math.min(limit, value));
	}
}
