/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.compiler;

import org.rei.vepl.runtime.MissionEvent;
import org.rei.vepl.runtime.Observation;
import org.rei.vepl.runtime.QueryEvent;
import org.rei.vepl.runtime.SignalSink;

/**
 * The Java side the generated DRL runs against: the package of the rules, the classes of query and mission events
 * (both with {@code subject} and a {@code timestamp} in milliseconds of simulation time), the interface they share
 * (with {@code getT()}, {@code getSubject()}, {@code getTarget()}, {@code getRange()}) and the type of the global
 * {@code signals}, which has {@code emit(String, Observation)} and {@code emit(String, double, String, String,
 * double)}. The query event class has a nested enum {@code Kind} with {@code FOUND} and {@code LOST}.
 */
public record DrlTarget(String drlPackage, String queryEvent, String missionEvent, String observation,
		String signalSink) {

	/**
	 * The classes of {@code org.rei.vepl.runtime}, which the monitor inserts and the tests run the rules with. They
	 * live beside the compiler, not in the monitor (which depends on this module), so that the monitor and the VEPL
	 * tests run one set of classes, and a renamed class breaks the build here rather than the rules at run time.
	 */
	public static final DrlTarget MONITOR = new DrlTarget("rei", QueryEvent.class.getName(),
			MissionEvent.class.getName(), Observation.class.getName(), SignalSink.class.getName());

	static String simpleName(String fqn) {
		return fqn.substring(fqn.lastIndexOf('.') + 1);
	}
}
