/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.runtime;

/**
 * Where the generated rules send signals (the DRL global {@code signals}): the monitor's publisher, or a recorder
 * in tests.
 */
public interface SignalSink {

	/** Emits {@code signal} about the observation that raised it. */
	default void emit(String signal, Observation o) {
		emit(signal, o.getT(), o.getSubject(), o.getTarget(), o.getRange());
	}

	void emit(String signal, double t, String subject, String object, double distance);
}
