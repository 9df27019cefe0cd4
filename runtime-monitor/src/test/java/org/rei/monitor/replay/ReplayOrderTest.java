/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.rei.monitor.pipeline.TestRuns;

/**
 * A replay merges the two recordings in the order the sim-adapter publishes them: the state of a step, then the
 * mission events of that time (decided from that state), so the mission signal's distance is measured from it.
 */
class ReplayOrderTest {

	@Test
	void aMissionEventGoesAfterTheStateOfTheSameTime() throws IOException {
		MessageBufferPacker states = MessagePack.newDefaultBufferPacker();
		for (int k = 0; k < 6; k++) { // robot at (1 + t, 1), 20 Hz
			double t = k * 0.05;
			states.packMapHeader(4).packString("seq").packLong(k).packString("t").packDouble(t);
			states.packString("objects").packArrayHeader(0);
			states.packString("robot").packMapHeader(2).packString("name").packString("tb3").packString("pose")
					.packArrayHeader(4).packDouble(1 + t).packDouble(1).packDouble(0).packDouble(0);
		}
		MessageBufferPacker missions = MessagePack.newDefaultBufferPacker();
		mission(missions, 0, 0.0, "BEGIN", -1, null);
		mission(missions, 1, 0.10, "TASK_START", 0, new double[] { 5, 1, 0 }); // = the time of state 2
		mission(missions, 2, 0.12, "TASK_FAIL", 0, new double[] { 5, 1, 0 }); // between states 2 and 3
		mission(missions, 3, 0.25, "END", -1, null); // the time of the last state
		try (TestRuns run = new TestRuns()) {
			Replayer.replay(run.monitor, Recording.of(states.toByteArray()), Recording.of(missions.toByteArray()));
			assertEquals(List.of("SIG_MISSION_BEGIN 0.000 mission 0.0000", "SIG_MISSION_TASK_START 0.100 task_0 3.9000",
					"SIG_MISSION_TASK_FAIL 0.120 task_0 3.9000", "SIG_MISSION_END 0.250 mission 0.0000"),
					run.of("SIG_MISSION_").stream()
							.map(s -> String.format("%s %.3f %s %.4f", s.signal(), s.t(), s.object(), s.distance()))
							.toList());
			assertEquals(6, run.monitor.statesProcessed());
			assertEquals(1.25, run.monitor.model().object("tb3").getPose().getX(), 1e-12, "END after the last state");
		}
	}

	private static void mission(MessageBufferPacker p, long seq, double t, String event, int task, double[] goal)
			throws IOException {
		p.packMapHeader(5).packString("seq").packLong(seq).packString("t").packDouble(t).packString("event")
				.packString(event).packString("task_index").packInt(task).packString("goal");
		if (goal == null) {
			p.packNil();
		} else {
			p.packArrayHeader(3).packDouble(goal[0]).packDouble(goal[1]).packDouble(goal[2]);
		}
	}
}
