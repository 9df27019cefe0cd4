/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/** A planar velocity: forward speed {@code v} (m/s) and turn rate {@code w} (rad/s). */
public record Twist(double v, double w) {
}
