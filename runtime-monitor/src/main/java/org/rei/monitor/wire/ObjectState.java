/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wire;

/** One entry of a state message's {@code objects}: pose {@code [x, y, z, yaw]}, twist {@code [vx, vy, wz]}. */
public record ObjectState(String name, String category, double x, double y, double z, double yaw, double vx,
		double vy, double wz) {
}
