/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.replay;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.monitor.pipeline.TestRuns;
import org.rei.monitor.pipeline.TracesAccess;
import org.rei.monitor.signals.Signal;

/** A stream written by the Python side (rei.wamp.codec + rei.wamp.recording) replays to the expected signals. */
class PythonStreamReplayTest {

	static Path writeWithPython(Path out) throws IOException, InterruptedException {
		Path repo = Path.of(System.getProperty("rei.repo", "..")).toAbsolutePath().normalize();
		Path python = repo.resolve(".venv/bin/python");
		Path script = Path.of(System.getProperty("user.dir")).resolve("src/test/resources/write_trace.py");
		Process p = new ProcessBuilder(python.toString(), script.toString(), TestRuns.roomFolder().toString(),
				out.toString()).redirectErrorStream(true).start();
		String output = new String(p.getInputStream().readAllBytes());
		assertEquals(0, p.waitFor(), "write_trace.py failed: " + output);
		return out.resolve("streams");
	}

	@Test
	void pythonRecordingGivesTheSameTransitionsAsTheJavaScript(@TempDir Path tmp) throws Exception {
		Path streams = writeWithPython(tmp.resolve("a"));
		List<Signal> expected;
		try (TestRuns java = new TestRuns()) {
			TracesAccess.wallApproach().forEach(java.monitor::onState);
			expected = java.signals;
		}
		try (TestRuns run = new TestRuns()) {
			Recording states = Recording.read(streams.resolve("state.msgpack"));
			Recording missions = Recording.read(streams.resolve("mission.msgpack"));
			assertEquals(281, states.size());
			assertEquals(4, missions.size());
			Replayer.replay(run.monitor, states, missions);
			assertEquals(Map.of(), run.monitor.guard().problems());
			assertEquals(10, expected.size()); // Table 2's 8 + the wall's per-object collision begin and end
			assertEquals(strip(expected), strip(run.signals.stream()
					.filter(s -> !s.signal().startsWith("SIG_MISSION_")).toList()));
			assertEquals(List.of("SIG_MISSION_BEGIN 0.000 mission", "SIG_MISSION_TASK_START 0.000 task_0",
					"SIG_MISSION_TASK_FAIL 10.000 task_0", "SIG_MISSION_END 14.000 mission"),
					run.of("SIG_MISSION_").stream()
							.map(s -> s.signal() + " " + String.format("%.3f", s.t()) + " " + s.object()).toList());
			// full frames repeat the statics at their world.json poses: nothing moved, nothing unknown
			assertEquals(6.0 - 0.1405 - 0.15 * 4, run.monitor.model().object("tb3").getPose().getX(), 1e-9);
		}
	}

	@Test
	void pythonRecordingIsDeterministic(@TempDir Path tmp) throws Exception {
		Path a = writeWithPython(tmp.resolve("a"));
		Path b = writeWithPython(tmp.resolve("b"));
		assertArrayEquals(Files.readAllBytes(a.resolve("state.msgpack")), Files.readAllBytes(b.resolve("state.msgpack")));
		assertFalse(Recording.read(a.resolve("state.msgpack")).truncated());
	}

	private static List<String> strip(List<Signal> signals) {
		return signals.stream().map(s -> s.signal() + " " + String.format("%.3f %s %.4f", s.t(), s.object(), s.distance()))
				.toList();
	}
}
