/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.runtime;

import java.util.List;

/**
 * An event of the mission topic in the session: {@code event} is BEGIN, TASK_START, TASK_SUCCESS, TASK_FAIL or END;
 * the target is {@code mission} or {@code task_<index>}, the range the robot's distance to the task's goal.
 */
public final class MissionEvent extends SessionEvent {

	public static final String BEGIN = "BEGIN";
	public static final String TASK_START = "TASK_START";
	public static final String TASK_SUCCESS = "TASK_SUCCESS";
	public static final String TASK_FAIL = "TASK_FAIL";
	public static final String END = "END";
	/**
	 * The events of the mission topic: Java's one copy of {@code mission_events} in contract/vocabulary.json
	 * (checked by tests/foundation/test_vocabulary_contract.py).
	 */
	public static final List<String> KINDS = List.of(BEGIN, TASK_START, TASK_SUCCESS, TASK_FAIL, END);

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
