/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.runtime;

import java.util.ArrayList;
import java.util.List;

/**
 * An event of the mission topic in the session: {@code event} is BEGIN, TASK_START, TASK_SUCCESS, TASK_FAIL or END,
 * or a fault window's edge ({@link #FAULT_EVENTS});
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
	/**
	 * The fault window edges the simulation sends on the mission topic, {@code FAULT_<SENSOR>_<KIND>_BEGIN/_END}:
	 * Java's one copy of {@code faults} in contract/vocabulary.json (checked by test_vocabulary_contract.py). They
	 * concern no task; the default patterns (faults.vepl) publish each as the signal {@code SIG_} + its name.
	 */
	public static final List<String> FAULT_EVENTS = concat(concat(concat(concat(
			faultEvents("LASER", List.of("IMPULSE", "FREEZE", "BLACKOUT", "OCCLUSION", "NOISE")),
			faultEvents("ODOMETRY", List.of("DRIFT", "JUMP"))),
			faultEvents("DRIVE", List.of("SLIP", "STUCK"))),
			faultEvents("COMMANDS", List.of("LATENCY", "LOSS"))),
			faultEvents("POSE", List.of("KIDNAP")));
	/** Every event the mission topic carries: {@link #KINDS} then {@link #FAULT_EVENTS}. */
	public static final List<String> ALL = concat(KINDS, FAULT_EVENTS);

	private final String event;
	private final int taskIndex;

	/** @param taskIndex the task's index, or -1 for an event of the whole mission */
	public MissionEvent(String event, int taskIndex, String subject, double range, double t) {
		super(subject, taskIndex >= 0 ? "task_" + taskIndex : "mission", range, t);
		this.event = event;
		this.taskIndex = taskIndex;
	}

	/** @return whether {@code event} is a fault window's edge rather than a mission or task event */
	public static boolean isFault(String event) {
		return FAULT_EVENTS.contains(event);
	}

	private static List<String> faultEvents(String sensor, List<String> kinds) {
		List<String> out = new ArrayList<>();
		for (String kind : kinds) {
			out.add("FAULT_" + sensor + "_" + kind + "_BEGIN");
			out.add("FAULT_" + sensor + "_" + kind + "_END");
		}
		return List.copyOf(out);
	}

	private static List<String> concat(List<String> a, List<String> b) {
		List<String> out = new ArrayList<>(a);
		out.addAll(b);
		return List.copyOf(out);
	}

	public String getEvent() {
		return event;
	}

	public int getTaskIndex() {
		return taskIndex;
	}
}
