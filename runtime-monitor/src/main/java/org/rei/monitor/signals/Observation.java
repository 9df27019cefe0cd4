/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.signals;

/** What a signal is about: who, what, how far, when (simulation seconds). Facts that raise signals have these. */
public interface Observation {

	String getSubject();

	String getTarget();

	double getRange();

	double getT();
}
