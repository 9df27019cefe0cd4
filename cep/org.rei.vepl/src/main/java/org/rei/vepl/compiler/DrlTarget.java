/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.compiler;

/**
 * The Java side the generated DRL runs against: the package of the rules, the classes of query and mission events
 * (both with {@code subject} and a {@code timestamp} in milliseconds of simulation time), the interface they share
 * (with {@code getT()}, {@code getSubject()}, {@code getTarget()}, {@code getRange()}) and the type of the global
 * {@code signals}, which has {@code emit(String, Observation)} and {@code emit(String, double, String, String,
 * double)}. The query event class has a nested enum {@code Kind} with {@code FOUND} and {@code LOST}.
 */
public record DrlTarget(String drlPackage, String queryEvent, String missionEvent, String observation,
		String signalSink) {

	/** The runtime monitor's classes (org.rei.monitor.engine / .signals). */
	public static final DrlTarget MONITOR = new DrlTarget("rei", "org.rei.monitor.engine.QueryEvent",
			"org.rei.monitor.engine.MissionEvent", "org.rei.monitor.signals.Observation",
			"org.rei.monitor.signals.SignalSink");

	static String simpleName(String fqn) {
		return fqn.substring(fqn.lastIndexOf('.') + 1);
	}
}
