/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.wire.StateMessage;

/** Malformed and out-of-order messages are counted, logged once per kind and skipped; gaps become signals. */
class BadInputTest {

	private static byte[] bytes(MessageBufferPacker p) {
		return p.toByteArray();
	}

	@Test
	void malformedMessagesAreCountedLoggedOnceAndSkipped() throws IOException {
		try (TestRuns run = new TestRuns()) {
			List<StateMessage> trace = Traces.wallApproach();
			MessageBufferPacker notAMap = MessagePack.newDefaultBufferPacker();
			notAMap.packArrayHeader(1).packInt(3);
			MessageBufferPacker noRobot = MessagePack.newDefaultBufferPacker();
			noRobot.packMapHeader(3).packString("seq").packInt(0).packString("t").packDouble(0)
					.packString("objects").packArrayHeader(0);
			MessageBufferPacker badPose = MessagePack.newDefaultBufferPacker();
			badPose.packMapHeader(4).packString("seq").packInt(0).packString("t").packDouble(0).packString("objects")
					.packArrayHeader(0).packString("robot").packMapHeader(2).packString("name").packString("tb3")
					.packString("pose").packArrayHeader(2).packDouble(1).packDouble(2);
			for (int i = 0; i < 3; i++) {
				run.monitor.onStateBytes(new byte[] { (byte) 0xc1, 1, 2 }, 0, 3); // 0xc1 is never used by msgpack
				run.monitor.onStateBytes(bytes(notAMap), 0, bytes(notAMap).length);
				run.monitor.onStateBytes(bytes(noRobot), 0, bytes(noRobot).length);
				run.monitor.onStateBytes(bytes(badPose), 0, bytes(badPose).length);
				run.monitor.onMissionBytes(new byte[0], 0, 0);
			}
			trace.forEach(run.monitor::onState);
			Map<String, Long> problems = run.monitor.guard().problems();
			assertEquals(3L, problems.get("not-a-map"));
			assertEquals(3L, problems.get("missing-field"));
			assertEquals(3L, problems.get("bad-field"));
			assertEquals(3L, problems.get("undecodable-state"));
			assertEquals(3L, problems.get("empty"));
			assertEquals(problems.size(), run.log.size(), "one log line per kind: " + run.log);
			assertEquals(10, run.signals.size(), "the good messages still give every transition (8 + the wall's per-object 2)");
			assertEquals(281, run.monitor.statesProcessed());
		}
	}

	@Test
	void arrayLengthsClaimedByAFewBytesAllocateNothing() {
		try (TestRuns run = new TestRuns()) {
			// "objects": array32 of 2^31 - 1 entries, then the message ends
			byte[] objects = { (byte) 0x82, (byte) 0xa3, 's', 'e', 'q', 0, (byte) 0xa7, 'o', 'b', 'j', 'e', 'c', 't',
					's', (byte) 0xdd, 0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff };
			// "robot": {"laser_ranges": array32 of 2^31 - 1 numbers}
			byte[] ranges = { (byte) 0x81, (byte) 0xa5, 'r', 'o', 'b', 'o', 't', (byte) 0x81, (byte) 0xac, 'l', 'a', 's',
					'e', 'r', '_', 'r', 'a', 'n', 'g', 'e', 's', (byte) 0xdd, 0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff };
			run.monitor.onStateBytes(objects, 0, objects.length);
			run.monitor.onStateBytes(ranges, 0, ranges.length);
			// the first ends where the first object should start ("empty"), the second is refused by its length
			assertEquals(Map.of("empty", 1L, "bad-field", 1L), run.monitor.guard().problems());
			Traces.wallApproach().forEach(run.monitor::onState);
			assertEquals(281, run.monitor.statesProcessed());
		}
	}

	@Test
	void oldRepeatedAndBackwardMessagesAreSkipped() {
		try (TestRuns run = new TestRuns()) {
			List<StateMessage> trace = Traces.wallApproach();
			for (int k = 0; k < trace.size(); k++) {
				run.monitor.onState(trace.get(k));
				if (k == 170) {
					run.monitor.onState(trace.get(k)); // repeated
					run.monitor.onState(trace.get(5)); // old
					StateMessage m = trace.get(k + 1);
					run.monitor.onState(new StateMessage(m.seq(), trace.get(3).t(), false, m.objects(), m.robot(),
							m.contacts())); // right seq, but time runs backwards: rejected, so the real k + 1 still fits
				}
			}
			assertEquals(3L, run.monitor.guard().count("out-of-order-state"));
			assertEquals(281, run.monitor.statesProcessed());
			assertEquals(10, run.signals.size()); // Table 2's 8 + the wall's per-object collision begin and end
		}
	}

	@Test
	void aGapInSeqIsReportedAsSignalAndMonitoringGoesOn() {
		try (TestRuns run = new TestRuns()) {
			List<StateMessage> trace = Traces.wallApproach();
			for (int k = 0; k < trace.size(); k++) {
				if (k < 100 || k > 103) { // seq 100..103 lost
					run.monitor.onState(trace.get(k));
				}
			}
			List<Signal> gaps = run.of("SIG_MONITOR_DATA_GAP");
			assertEquals(1, gaps.size());
			assertEquals(104 * 0.05, gaps.get(0).t(), 1e-9);
			assertEquals("state", gaps.get(0).object());
			assertEquals(4.0, gaps.get(0).distance(), 0);
			assertEquals(11, run.signals.size()); // 10 + the data gap
			for (int i = 0; i < run.signals.size(); i++) {
				assertEquals(i, run.signals.get(i).seq());
			}
			assertTrue(run.log.stream().anyMatch(l -> l.contains("gap-state")));
		}
	}
}
