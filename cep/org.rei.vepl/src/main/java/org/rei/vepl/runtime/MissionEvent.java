/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.runtime;

/**
 * An event of the mission topic in the session: {@code event} is BEGIN, TASK_START, TASK_SUCCESS, TASK_FAIL or END;
 * the target is {@code mission} or {@code task_<index>}, the range the robot's distance to the task's goal.
 */
public final class MissionEvent extends SessionEvent {

	private final String event;
	private final int taskIndex;

	/** @param taskIndex the task's index, or -1 for an event of the whole mission */
	public MissionEvent(String event, int taskIndex, String subject, double range, double t) {
		super(subject, taskIndex >= 0 ? "task_" + taskIndex : "mission", range, t);
		this.event = event;
		this.taskIndex = taskIndex;
	}

	public String getEvent() {
		return event;
	}

	public int getTaskIndex() {
		return taskIndex;
	}
}
