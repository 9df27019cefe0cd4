/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.monitor.model.Snapshots;
import org.rei.monitor.pipeline.TestRuns;
import org.rei.monitor.pipeline.TracesAccess;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** {@code SnapshotCheck} reloads a snapshot file into EMF and reports it (used by tests/monitor from Python). */
class SnapshotCheckTest {

	@Test
	void aSnapshotFileReloadsAndIsSummarised(@TempDir Path tmp) throws Exception {
		Path file = tmp.resolve("s.xmi");
		try (TestRuns run = new TestRuns()) {
			TracesAccess.wallApproach().subList(0, 101).forEach(run.monitor::onState);
			Snapshots.save(run.monitor.model().resource(), file);
		}
		ByteArrayOutputStream out = new ByteArrayOutputStream();
		int code = SnapshotCheck.run(new String[] { file.toString() }, new PrintStream(out, true, StandardCharsets.UTF_8),
				System.err);
		assertEquals(0, code);
		JsonNode s = new ObjectMapper().readTree(out.toString(StandardCharsets.UTF_8));
		assertEquals("test", s.get("runId").asText());
		assertEquals(5.0, s.get("time").asDouble(), 1e-12);
		assertEquals("tb3", s.get("robot").get("name").asText());
		assertEquals("Waffle", s.get("robot").get("type").asText());
		assertEquals(5.0, s.get("robot").get("pose").get(0).asDouble(), 1e-12);
		assertEquals("F_5_1", s.get("robot").get("standsOn").asText());
		assertEquals(0, s.get("untypedObjects").size(), s.toString());
	}

	@Test
	void somethingElseIsRefused(@TempDir Path tmp) throws Exception {
		Path file = tmp.resolve("bad.xmi");
		Files.writeString(file, "<not-xmi/>");
		ByteArrayOutputStream err = new ByteArrayOutputStream();
		PrintStream errs = new PrintStream(err, true, StandardCharsets.UTF_8);
		assertEquals(1, SnapshotCheck.run(new String[] { file.toString() }, System.out, errs));
		assertTrue(err.toString(StandardCharsets.UTF_8).startsWith("snapshot-check: "));
		assertEquals(2, SnapshotCheck.run(new String[0], System.out, errs));
	}
}
