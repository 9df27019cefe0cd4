/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.rei.monitor.pipeline.Monitor;
import org.rei.monitor.pipeline.TestRuns;
import org.rei.monitor.pipeline.TracesAccess;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.wire.MalformedMessageException;
import org.rei.monitor.wire.StateMessage;
import org.rei.monitor.wire.WireDecoder;

/** Short, seeded campaigns of {@link WireFuzzer} plus the stream-level properties it cannot check alone. */
class WireFuzzTest {

	@Test
	void mutatedMessagesNeverThrowNorHangAndAreAllAccountedFor() {
		try (WireFuzzer fuzzer = new WireFuzzer(15_000)) {
			Runtime rt = Runtime.getRuntime();
			WireFuzzer.Result r = fuzzer.run(20261122L, 6000, 15);
			System.out.println("wire fuzz: " + r.messages() + " messages, " + r.processed() + " processed, problems "
					+ r.problems() + ", heap " + (rt.totalMemory() - rt.freeMemory()) / (1 << 20) + " MB");
			assertTrue(r.failures().isEmpty(), () -> r.failures().size() + " failures: "
					+ String.join("\n", r.failures().subList(0, Math.min(5, r.failures().size()))));
			assertTrue(r.messages() > 500, "too few messages in the time box: " + r.messages());
			// the huge lengths must not have been allocated: anything near 2^31 elements would not fit this heap
			assertTrue(rt.totalMemory() - rt.freeMemory() < rt.maxMemory(), "heap");
		}
	}

	private static List<String> signalsOf(TestRuns run) {
		return run.signals.stream().map(s -> s.signal() + "@" + s.t() + "/" + s.object()).toList();
	}

	/** Rejected garbage between the messages of a valid stream changes nothing the valid stream produces. */
	@Test
	void validMessagesInterleavedWithGarbageGiveTheSameSignals() {
		List<StateMessage> trace = TracesAccess.wallApproach();
		List<byte[]> valid = trace.stream().map(m -> WireFuzzer.pack(WireFuzzer.stateTree(m))).toList();
		List<String> clean;
		try (TestRuns run = new TestRuns()) {
			valid.forEach(b -> run.monitor.onStateBytes(b, 0, b.length));
			clean = signalsOf(run);
			assertEquals(10, clean.size()); // Table 2's 8 + the wall's per-object collision begin and end
		}
		Random random = new Random(7);
		try (WireFuzzer fuzzer = new WireFuzzer(5_000); TestRuns run = new TestRuns()) {
			long injected = 0;
			for (int k = 0; k < trace.size(); k++) {
				assertNull(fuzzer.feed(run.monitor, true, valid.get(k)));
				for (int i = random.nextInt(6); i > 0; i--) {
					// mutants of this (already applied) message: if one still decodes its seq is old, so it is skipped
					Object[] bad = WireFuzzer.mutate(WireFuzzer.stateTree(trace.get(k)), random);
					byte[] b = (byte[]) bad[1];
					if (!rejected(b, k)) {
						continue;
					}
					assertNull(fuzzer.feed(run.monitor, true, b), () -> "mutation " + bad[0]);
					injected++;
				}
				byte[] junk = new byte[random.nextInt(40)];
				random.nextBytes(junk);
				assertNull(fuzzer.feed(run.monitor, false, junk));
				injected++;
			}
			assertEquals(clean, signalsOf(run), "the garbage changed the signals");
			assertEquals(trace.size(), run.monitor.statesProcessed());
			long counted = WireFuzzer.totalProblems(run.monitor);
			long gaps = run.monitor.guard().count("gap-state");
			assertEquals(0, gaps);
			assertEquals(injected, counted + run.monitor.missionsProcessed(), "every injected message is counted");
			assertTrue(injected > 500, "injected " + injected);
		}
	}

	/** Would the monitor skip {@code b} after applying seq {@code k}: undecodable, old seq or no later time. */
	private static boolean rejected(byte[] b, int k) {
		try {
			StateMessage m = WireDecoder.decodeState(b);
			return m.seq() <= k || !"tb3".equals(m.robot().name());
		} catch (MalformedMessageException e) {
			return true;
		}
	}

	/** Regression: a NaN or infinite pose was accepted and failed in the geometry ("failed-state"). */
	@Test
	void nonFinitePosesAreRefusedByTheDecoder() {
		List<StateMessage> trace = TracesAccess.wallApproach();
		try (TestRuns run = new TestRuns()) {
			for (int k = 0; k < trace.size(); k++) {
				java.util.Map<String, Object> tree = WireFuzzer.stateTree(trace.get(k));
				@SuppressWarnings("unchecked")
				java.util.Map<String, Object> robot = (java.util.Map<String, Object>) tree.get("robot");
				robot.put("pose", new ArrayList<>(List.of(Double.NaN, 1.0, 0.0, k % 2 == 0 ? Double.POSITIVE_INFINITY : 0.0)));
				byte[] bad = WireFuzzer.pack(tree);
				run.monitor.onStateBytes(bad, 0, bad.length);
				byte[] good = WireFuzzer.pack(WireFuzzer.stateTree(trace.get(k)));
				run.monitor.onStateBytes(good, 0, good.length);
			}
			assertEquals(Map.of("bad-field", (long) trace.size()), run.monitor.guard().problems());
			assertEquals(10, run.signals.size());
		}
	}

	/** A huge seq is taken as a (reported) gap; later smaller seqs are old: counted, never a crash or overflow. */
	@Test
	void hugeSeqIsAGapThenEverythingIsOld() {
		List<StateMessage> trace = TracesAccess.wallApproach();
		try (TestRuns run = new TestRuns()) {
			StateMessage m = trace.get(1);
			for (long seq : new long[] { Long.MAX_VALUE, Long.MAX_VALUE - 1, 0, 5 }) {
				byte[] b = WireFuzzer.pack(WireFuzzer.stateTree(new StateMessage(seq, m.t(), false, m.objects(),
						m.robot(), m.contacts())));
				run.monitor.onStateBytes(b, 0, b.length);
			}
			assertEquals(1, run.of(Monitor.DATA_GAP).size());
			assertEquals(3, run.monitor.guard().count("out-of-order-state"));
			assertEquals(1, run.monitor.statesProcessed());
		}
	}

	/** Dropped, duplicated and swapped messages: every gap is one data-gap signal, every old one counted. */
	@Test
	void seqGapsDuplicatesAndReorderingFollowTheSequenceRules() {
		List<StateMessage> trace = TracesAccess.wallApproach();
		for (long seed = 1; seed <= 3; seed++) {
			Random random = new Random(seed);
			List<Integer> order = new ArrayList<>();
			for (int k = 0; k < trace.size(); k++) {
				int roll = random.nextInt(20);
				if (roll == 0) {
					continue; // lost
				}
				order.add(k);
				if (roll == 1) {
					order.add(k); // duplicated
				} else if (roll == 2 && order.size() > 1) {
					int last = order.size() - 1;
					order.set(last, order.get(last - 1));
					order.set(last - 1, k); // swapped with the one before
				}
			}
			// the sequence rules, independently: old or repeated is skipped, a jump forward is a gap then used
			long next = 0;
			long outOfOrder = 0;
			List<Double> gapDistances = new ArrayList<>();
			for (int k : order) {
				if (k < next) {
					outOfOrder++;
				} else {
					if (k > next) {
						gapDistances.add((double) (k - next));
					}
					next = k + 1;
				}
			}
			try (TestRuns run = new TestRuns()) {
				for (int k : order) {
					byte[] b = WireFuzzer.pack(WireFuzzer.stateTree(trace.get(k)));
					run.monitor.onStateBytes(b, 0, b.length);
				}
				List<Signal> gaps = run.of(Monitor.DATA_GAP);
				assertEquals(gapDistances, gaps.stream().map(Signal::distance).toList(), "seed " + seed);
				assertEquals(outOfOrder, run.monitor.guard().count("out-of-order-state"), "seed " + seed);
				assertTrue(!gaps.isEmpty() && outOfOrder > 0, "the seed exercises both");
				for (int i = 0; i < run.signals.size(); i++) {
					assertEquals(i, run.signals.get(i).seq(), "signal seq without gaps");
				}
				assertEquals(Map.of(), Map.of());
			}
		}
	}
}
