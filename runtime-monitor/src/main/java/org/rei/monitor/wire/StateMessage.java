/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wire;

import java.util.List;

/**
 * A message of {@code rei.run.<id>.state} (docs/protocol.md). {@code contacts} is null when the collector does not
 * report contacts, and holds the body-name pairs touching in this step otherwise.
 */
public record StateMessage(long seq, double t, boolean full, List<ObjectState> objects, RobotState robot,
		List<String[]> contacts) {
}
