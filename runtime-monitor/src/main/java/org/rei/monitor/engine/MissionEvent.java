/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import org.rei.monitor.signals.Observation;

/**
 * An event of the mission topic in the session: {@code event} is BEGIN, TASK_START, TASK_SUCCESS, TASK_FAIL or END;
 * the target is {@code mission} or {@code task_<index>}, the range the robot's distance to the task's goal.
 */
public final class MissionEvent implements Observation {

	private final String event;
	private final int taskIndex;
	private final String subject;
	private final String target;
	private final double range;
	private final double t;
	private final long timestamp;

	public MissionEvent(String event, int taskIndex, String subject, double range, double t) {
		this.event = event;
		this.taskIndex = taskIndex;
		this.subject = subject;
		this.target = taskIndex >= 0 ? "task_" + taskIndex : "mission";
		this.range = range;
		this.t = t;
		this.timestamp = Math.round(t * 1000);
	}

	public String getEvent() {
		return event;
	}

	public int getTaskIndex() {
		return taskIndex;
	}

	@Override
	public String getSubject() {
		return subject;
	}

	@Override
	public String getTarget() {
		return target;
	}

	@Override
	public double getRange() {
		return range;
	}

	@Override
	public double getT() {
		return t;
	}

	public long getTimestamp() {
		return timestamp;
	}
}
