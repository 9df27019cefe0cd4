/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wire;

/** A message of {@code rei.run.<id>.mission}; {@code goal} is null for BEGIN and END, {@code reason} optional. */
public record MissionMessage(long seq, double t, String event, int taskIndex, double[] goal, String reason) {
}
