/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.compiler;

import java.util.List;
import java.util.Map;

/**
 * The DRL compiled from a set of .vepl files: a prologue that declares the events and the bookkeeping facts, then
 * one DRL file per .vepl file (same base name); the utility of every declared signal (null: none declared), and the
 * zone change of every signal declared with a {@code transition}.
 */
public record CompiledRules(List<DrlFile> files, Map<String, Double> utilities, Map<String, Transition> transitions,
		long retentionMillis) {

	/**
	 * A change of zone: {@code source} GEOM or LASER, {@code from}/{@code to} FAR, CLOSE, COLLISION; the robot's
	 * single zone, or {@code perObject} the zone of the signal's object.
	 */
	public record Transition(String source, String from, String to, boolean perObject) {
	}

	/** One generated .drl file. */
	public record DrlFile(String name, String text) {
	}
}
