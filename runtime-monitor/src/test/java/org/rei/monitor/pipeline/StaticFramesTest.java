/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.rei.monitor.model.Snapshots;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.wire.ObjectState;
import org.rei.monitor.wire.RobotState;
import org.rei.monitor.wire.StateMessage;
import org.rei.monitor.wire.WireDecoder;

/**
 * Full frames that re-list static obstacles (other producers, older recordings): the monitor skips the entries that
 * repeat the last applied bytes, and still re-places a static that moved, whichever way it moved; full frames
 * without them (REI's collector) judge the same.
 */
class StaticFramesTest {

	// the test room: table1 (1.2 x 0.8) at (1.5, 2.5) spans y 2.1 .. 2.9; the robot (0.281 x 0.306) at (1.5, 1.5)
	// reaches y 1.653: 0.447 m apart (FAR). Moved to y = 2.2 the table's edge is at 1.8: 0.147 m (CLOSE).
	private static final double[] TABLE = { 1.5, 2.5, 0.375, 0 };
	private static final double[] TABLE_MOVED = { 1.5, 2.2, 0.375, 0 };
	private static final double[] WALL = { 6.05, 2.0, 0.5, 0 };

	private record Entry(String name, String type, double[] pose) {
	}

	private static Entry table(double[] pose) {
		return new Entry("table1", "STATIC", pose);
	}

	private static List<Entry> statics(double[] tablePose) {
		return List.of(new Entry("wall_east", "WALL", WALL), table(tablePose));
	}

	/** A state message in the collector's layout: seq, t, full?, objects, robot (at (1.5, 1.5), still). */
	static byte[] frame(long seq, boolean full, List<Entry> objects) {
		try (MessageBufferPacker p = MessagePack.newDefaultBufferPacker()) {
			p.packMapHeader(full ? 5 : 4);
			p.packString("seq").packLong(seq);
			p.packString("t").packDouble(seq * 0.05);
			if (full) {
				p.packString("full").packBoolean(true);
			}
			p.packString("objects").packArrayHeader(objects.size());
			for (Entry e : objects) {
				p.packMapHeader(4);
				p.packString("name").packString(e.name());
				p.packString("type").packString(e.type());
				p.packString("pose").packArrayHeader(4);
				for (double v : e.pose()) {
					p.packDouble(v);
				}
				p.packString("twist").packArrayHeader(3).packDouble(0).packDouble(0).packDouble(0);
			}
			p.packString("robot").packMapHeader(3);
			p.packString("name").packString("tb3");
			p.packString("pose").packArrayHeader(4).packDouble(1.5).packDouble(1.5).packDouble(0).packDouble(0);
			p.packString("twist").packArrayHeader(3).packDouble(0).packDouble(0).packDouble(0);
			return p.toByteArray();
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}

	private static void feed(TestRuns run, byte[] data) {
		run.monitor.onStateBytes(data, 0, data.length);
	}

	private static double tableY(TestRuns run) {
		return run.monitor.model().object("table1").getPose().getY();
	}

	private static List<String> geometry(TestRuns run) {
		return run.signals.stream().filter(s -> s.signal().startsWith("SIG_GEOM_"))
				.map(s -> s.signal() + " " + s.object() + " " + String.format("%.2f", s.t())).toList();
	}

	@Test
	void unchangedStaticsAreSkippedAndAMovedOneIsReplacedBothWays() {
		try (TestRuns run = new TestRuns()) {
			feed(run, frame(0, true, statics(TABLE)));
			assertEquals(0, run.monitor.staticEntriesSkipped(), "the first full frame is decoded");
			feed(run, frame(1, false, List.of()));
			feed(run, frame(2, true, statics(TABLE)));
			assertEquals(2, run.monitor.staticEntriesSkipped(), "a repeated full frame is skipped");
			feed(run, frame(3, true, statics(TABLE_MOVED)));
			assertEquals(3, run.monitor.staticEntriesSkipped(), "only the wall: the table's bytes changed");
			assertEquals(2.2, tableY(run), 0);
			feed(run, frame(4, true, statics(TABLE_MOVED)));
			assertEquals(5, run.monitor.staticEntriesSkipped(), "the moved table's new bytes are the reference now");
			feed(run, frame(5, true, statics(TABLE)));
			assertEquals(2.5, tableY(run), 0, "moved back: its old bytes are not mistaken for unchanged");
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE table1 0.15", "SIG_GEOM_CLOSE_TRANSIT_FAR table1 0.25"),
					geometry(run));
			assertEquals(6, run.monitor.statesProcessed());
			assertTrue(run.monitor.guard().problems().isEmpty(), run.monitor.guard().problems().toString());
		}
	}

	@Test
	void aStaticMovedOutsideAFullFrameIsPutBackByTheNextFullFrame() {
		try (TestRuns run = new TestRuns()) {
			feed(run, frame(0, true, statics(TABLE)));
			feed(run, frame(1, false, List.of(table(TABLE_MOVED)))); // not the protocol's habit, but possible
			assertEquals(2.2, tableY(run), 0);
			feed(run, frame(2, true, statics(TABLE))); // byte-identical to frame 0's entry: must not be skipped
			assertEquals(2.5, tableY(run), 0);
			// the same through a message decoded elsewhere (no bytes known): the cache forgets the table
			StateMessage moved = new StateMessage(3, 0.15, false,
					List.of(new ObjectState("table1", "STATIC", 1.5, 2.2, 0.375, 0, 0, 0, 0)),
					new RobotState("tb3", 1.5, 1.5, 0, 0, 0, 0, 0, null, Double.NaN, null, null, Double.NaN), null);
			run.monitor.onState(moved);
			assertEquals(2.2, tableY(run), 0);
			feed(run, frame(4, true, statics(TABLE)));
			assertEquals(2.5, tableY(run), 0);
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE table1 0.05", "SIG_GEOM_CLOSE_TRANSIT_FAR table1 0.10",
					"SIG_GEOM_FAR_TRANSIT_CLOSE table1 0.15", "SIG_GEOM_CLOSE_TRANSIT_FAR table1 0.20"), geometry(run));
		}
	}

	@Test
	void anEntryAfterAChangeOfTheSameObjectInOneMessageIsApplied() {
		try (TestRuns run = new TestRuns()) {
			feed(run, frame(0, true, statics(TABLE)));
			// table1 twice: moved, then its unchanged bytes again at the array position where they were last time.
			// The last entry wins, as without the cache: the second must not be skipped as "unchanged".
			feed(run, frame(1, true, List.of(table(TABLE_MOVED), table(TABLE), new Entry("wall_east", "WALL", WALL))));
			assertEquals(2.5, tableY(run), 0);
			assertEquals(0, run.monitor.staticEntriesSkipped());
		}
	}

	@Test
	void unknownObjectsAreCountedInEveryFullFrameAndBadFramesStillFail() {
		try (TestRuns run = new TestRuns()) {
			List<Entry> withStranger = new ArrayList<>(statics(TABLE));
			withStranger.add(new Entry("stranger", "STATIC", new double[] { 3, 3, 0, 0 }));
			feed(run, frame(0, true, withStranger));
			feed(run, frame(1, true, withStranger));
			feed(run, frame(2, true, withStranger));
			assertEquals(3L, run.monitor.guard().count("unknown-object"));
			byte[] good = frame(3, true, statics(TABLE_MOVED));
			byte[] cut = Arrays.copyOf(good, good.length - 40); // ends inside the robot
			feed(run, cut);
			byte[] cutInStatics = frame(3, true, statics(TABLE));
			feed(run, Arrays.copyOf(cutInStatics, 60)); // ends inside the (skippable) wall entry
			assertEquals(2L, run.monitor.guard().count("undecodable-state"));
			assertEquals(2.5, tableY(run), 0, "nothing of a bad message is applied");
			feed(run, good);
			assertEquals(2.2, tableY(run), 0);
			assertEquals(4, run.monitor.statesProcessed());
		}
	}

	@Test
	void skippingGivesTheSameSignalsAndModelAsDecodingEverything() {
		List<byte[]> stream = new ArrayList<>();
		for (int k = 0; k < 200; k++) {
			boolean full = k % 20 == 0 || k % 7 == 0;
			double[] pose = (k / 30) % 2 == 0 ? TABLE : TABLE_MOVED;
			List<Entry> objects = new ArrayList<>();
			objects.add(new Entry("h1", "HUMAN", new double[] { 3.5, 3.5 - 0.01 * (k % 50), 0.85, 0 }));
			if (full) {
				objects.addAll(statics(pose));
			} else if (k % 30 == 0) {
				objects.add(table(pose));
			}
			stream.add(frame(k, full, objects));
		}
		try (TestRuns fast = new TestRuns(); TestRuns plain = new TestRuns()) {
			for (byte[] data : stream) {
				feed(fast, data);
				try {
					plain.monitor.onState(WireDecoder.decodeState(data));
				} catch (Exception e) {
					throw new AssertionError(e);
				}
			}
			assertTrue(fast.monitor.staticEntriesSkipped() > 30, "skipped " + fast.monitor.staticEntriesSkipped());
			assertEquals(0, plain.monitor.staticEntriesSkipped());
			assertEquals(lines(plain.signals), lines(fast.signals));
			assertTrue(fast.signals.size() >= 6, lines(fast.signals).toString());
			assertEquals(Snapshots.toXmi(plain.monitor.model().resource()),
					Snapshots.toXmi(fast.monitor.model().resource()));
		}
	}

	/**
	 * REI's collector no longer re-lists world.json's statics in full frames (docs/protocol.md): a stream whose full
	 * frames carry them at their world.json pose and the same stream without them give the same signals and model.
	 */
	@Test
	void fullFramesWithoutTheStaticsGiveTheSameSignalsAndModel() {
		try (TestRuns with = new TestRuns(); TestRuns without = new TestRuns()) {
			for (int k = 0; k < 200; k++) {
				boolean full = k % 20 == 0;
				// the human walks towards the robot's right side and stops beside it
				Entry human = new Entry("h1", "HUMAN", new double[] { Math.max(1.95, 3.5 - 0.01 * k), 1.5, 0.85, 0 });
				List<Entry> listed = new ArrayList<>(List.of(human));
				if (full) {
					listed.addAll(statics(TABLE));
				}
				feed(with, frame(k, full, listed));
				feed(without, frame(k, full, List.of(human)));
			}
			assertEquals(0, without.monitor.staticEntriesSkipped());
			assertTrue(with.monitor.staticEntriesSkipped() > 0);
			assertEquals(lines(with.signals), lines(without.signals));
			assertTrue(geometry(without).stream().anyMatch(s -> s.contains(" h1 ")), geometry(without).toString());
			assertEquals(Snapshots.toXmi(with.monitor.model().resource()),
					Snapshots.toXmi(without.monitor.model().resource()));
			assertTrue(without.monitor.guard().problems().isEmpty(), without.monitor.guard().problems().toString());
		}
	}

	private static List<String> lines(List<Signal> signals) {
		return signals.stream().map(Signal::line).toList();
	}
}
