/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/** State of the navigation goal as the SUT reports it (the action's feedback and result, docs/sut.md). */
public enum GoalStatus {
	/** Working on it. */
	ACTIVE,
	/** Reached: the mission executor checks this on the true pose ("false success" otherwise). */
	SUCCEEDED,
	/** Given up. */
	ABORTED,
	/** Withdrawn after a {@code cancel}. */
	CANCELLED;

	/** True once the goal is finished, whichever way. */
	public boolean isFinal() {
		return this != ACTIVE;
	}
}
