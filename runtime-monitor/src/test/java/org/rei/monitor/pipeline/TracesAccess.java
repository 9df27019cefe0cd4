/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import java.util.List;

import org.rei.monitor.wire.StateMessage;

/** The scripted traces for tests in other packages. */
public final class TracesAccess {

	private TracesAccess() {
	}

	public static List<StateMessage> wallApproach() {
		return Traces.wallApproach();
	}

	public static List<StateMessage> humanCrossing() {
		return Traces.humanCrossing();
	}
}
