/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.runtime;

/**
 * What a signal is about: who, what, how far, when (simulation seconds). The events the generated rules match have
 * these, so a rule can report its match's latest event whichever of its events that is.
 */
public interface Observation {

	String getSubject();

	String getTarget();

	double getRange();

	double getT();
}
