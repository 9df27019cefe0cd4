/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;

import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.rei.monitor.config.CaseReader;
import org.rei.monitor.pipeline.TestRuns;
import org.rei.monitor.wire.MalformedMessageException;
import org.rei.monitor.wire.MissionMessage;
import org.rei.monitor.wire.WireDecoder;
import org.rei.runtime.TaskStatus;
import org.rei.vepl.runtime.MissionEvent;

/**
 * A fault window's edge on the mission topic (docs/faults.md): the decoder takes the contract's fault events and
 * no other name, and the runtime model's mission and tasks do not change (no task -1 appears).
 */
class FaultEventsTest {

	private static byte[] mission(String event, int taskIndex) throws IOException {
		try (MessageBufferPacker out = MessagePack.newDefaultBufferPacker()) {
			out.packMapHeader(6);
			out.packString("seq").packLong(3);
			out.packString("t").packDouble(5.0);
			out.packString("event").packString(event);
			out.packString("task_index").packInt(taskIndex);
			out.packString("goal").packNil();
			out.packString("reason").packString("laser blackout, from 5 s to 8 s");
			return out.toByteArray();
		}
	}

	@Test
	void faultEdgesAreDecodedAndLeaveTheMissionStateAlone() throws Exception {
		// which events there are is the contract test's to check against contract/vocabulary.json
		assertTrue(MissionEvent.FAULT_EVENTS.contains("FAULT_LASER_BLACKOUT_BEGIN"));
		assertTrue(MissionEvent.FAULT_EVENTS.contains("FAULT_POSE_KIDNAP_END"));
		assertTrue(MissionEvent.FAULT_EVENTS.stream().allMatch(e -> e.endsWith("_BEGIN") || e.endsWith("_END")));
		MissionMessage begin = WireDecoder.decodeMission(mission("FAULT_LASER_BLACKOUT_BEGIN", -1));
		assertEquals("FAULT_LASER_BLACKOUT_BEGIN", begin.event());
		assertEquals(-1, begin.taskIndex());
		assertTrue(MissionEvent.isFault(begin.event()));
		CaseReader.Case c = TestRuns.room();
		RuntimeModelUpdater u = RuntimeModelUpdater.create("r1", c.world(), c.monitor());
		u.applyMission(new MissionMessage(0, 1.0, "TASK_START", 0, new double[] { 5.8, 1.0, 0 }, null));
		u.applyMission(begin);
		u.applyMission(WireDecoder.decodeMission(mission("FAULT_LASER_BLACKOUT_END", -1)));
		var state = u.model().getOwnedMissionState();
		assertEquals(1, state.getOwnedTasks().size());
		assertEquals(TaskStatus.ACTIVE, state.getOwnedTasks().get(0).getStatus());
		assertEquals(false, state.isEnded());
	}

	@Test
	void aFaultEventTheContractDoesNotNameIsRefused() {
		MalformedMessageException e = assertThrows(MalformedMessageException.class,
				() -> WireDecoder.decodeMission(mission("FAULT_LASER_SMOKE_BEGIN", -1)));
		assertTrue(e.getMessage().contains("unknown mission event FAULT_LASER_SMOKE_BEGIN"), e.getMessage());
	}
}
