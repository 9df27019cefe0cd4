/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.compiler;

import java.util.List;
import java.util.Map;

/**
 * The DRL compiled from a set of .vepl files: a prologue that declares the events and the bookkeeping facts, then
 * one DRL file per .vepl file (same base name); and the utility of every declared signal.
 */
public record CompiledRules(List<DrlFile> files, Map<String, Double> utilities, long retentionMillis) {

	/** One generated .drl file. */
	public record DrlFile(String name, String text) {
	}
}
