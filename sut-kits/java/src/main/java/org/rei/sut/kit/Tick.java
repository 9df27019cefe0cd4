/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/**
 * One control period: answer it with a {@link Command}.
 *
 * @param number    the tick, counted from 0 without gaps
 * @param t         the simulation clock (s): {@code number / control_rate} up to rounding
 * @param odom      wheel odometry in world (map) coordinates: {@code hello}'s start pose at tick 0, then drifting
 *                  from the true pose
 * @param odomTwist the velocity odometry measured
 * @param scan      the newest scan: taken since the previous tick if {@code scanIsNew}, else the last one (null
 *                  before the first)
 * @param scanIsNew whether {@code scan} arrived with this tick
 * @param goal      the latest goal, finished or not (null before the first): report its state with its methods
 */
public record Tick(long number, double t, Pose odom, Twist odomTwist, Scan scan, boolean scanIsNew, Goal goal) {
}
