/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.config;

import java.util.List;
import java.util.Map;

/**
 * monitor.json ({@code rei-monitor/1}): robot, thresholds {@code close} and {@code collision} in metres, topic
 * templates with {@code {run_id}} and the catalogue entries of the types the test case uses.
 */
public record MonitorSpec(String testcase, String robot, double epsClose, double epsCollision,
		Map<String, String> topics, List<CatalogueEntry> catalogue) {

	/** One catalogue type as monitor.json lists it. */
	public record CatalogueEntry(String name, String category, String shape, double[] size, double mass) {
	}

	/** What a run id may be: it becomes one component of every URI of the run (contract/vocabulary.json). */
	public static final String RUN_ID_PATTERN = "[A-Za-z0-9_-]{1,64}";
	/** A run's URIs when monitor.json names none: {@code rei.run.<run id>.<name>} (contract/vocabulary.json). */
	public static final String TOPIC_TEMPLATE = "rei.run.{run_id}.";

	/** The URI of topic {@code key} ({@code state}, {@code signal}, ...) for a run. */
	public String topic(String key, String runId) {
		String template = topics.getOrDefault(key,
				TOPIC_TEMPLATE + (key.equals("missionInfo") ? "mission_info" : key));
		return template.replace("{run_id}", runId);
	}
}
