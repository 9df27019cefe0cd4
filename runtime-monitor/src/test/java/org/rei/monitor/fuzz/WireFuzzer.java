/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.fuzz;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.rei.monitor.pipeline.Monitor;
import org.rei.monitor.pipeline.TestRuns;
import org.rei.monitor.pipeline.TracesAccess;
import org.rei.monitor.wire.ObjectState;
import org.rei.monitor.wire.RobotState;
import org.rei.monitor.wire.StateMessage;

/**
 * Hostile input for the monitor: valid state and mission messages of the test room (packed with msgpack-core,
 * as the collector does), mutated structurally (wrong types, NaN/inf/-0.0, missing and extra fields, huge
 * declared lengths, deep nesting, bad seq) and byte-wise (random bytes, flips, truncation), fed through
 * {@link Monitor#onStateBytes}/{@link Monitor#onMissionBytes} with the packaged rules. Every message must come
 * back within a time limit without an exception, and be either processed or counted as a problem of a named kind.
 */
public final class WireFuzzer implements AutoCloseable {

	/** A raw msgpack fragment written as is (headers that claim more than follows). */
	record Raw(byte[] bytes) {
	}

	/** The outcome of a campaign. */
	public record Result(long messages, long processed, Map<String, Long> problems, List<String> failures) {
	}

	private final long timeoutMillis;
	private ExecutorService worker = newWorker();

	public WireFuzzer(long timeoutMillis) {
		this.timeoutMillis = timeoutMillis;
	}

	private static ExecutorService newWorker() {
		return Executors.newSingleThreadExecutor(r -> {
			Thread t = new Thread(r, "wire-fuzz");
			t.setDaemon(true);
			return t;
		});
	}

	// ---- valid messages as trees, and their encoding ----

	static Map<String, Object> stateTree(StateMessage m) {
		Map<String, Object> root = new LinkedHashMap<>();
		root.put("seq", m.seq());
		root.put("t", m.t());
		if (m.full()) {
			root.put("full", true);
		}
		List<Object> objects = new ArrayList<>();
		for (ObjectState o : m.objects()) {
			Map<String, Object> e = new LinkedHashMap<>();
			e.put("name", o.name());
			e.put("type", o.category());
			e.put("pose", reals(o.x(), o.y(), o.z(), o.yaw()));
			e.put("twist", reals(o.vx(), o.vy(), o.wz()));
			objects.add(e);
		}
		root.put("objects", objects);
		RobotState r = m.robot();
		Map<String, Object> robot = new LinkedHashMap<>();
		robot.put("name", r.name());
		robot.put("pose", reals(r.x(), r.y(), r.z(), r.yaw()));
		robot.put("twist", reals(r.vx(), r.vy(), r.wz()));
		robot.put("odom", r.odom() == null ? null : reals(r.odom()));
		if (r.hasLaser()) {
			robot.put("laser_min", r.laserMin());
			robot.put("laser_ranges", reals(r.laserMin(), Double.POSITIVE_INFINITY, r.laserMin() + 1));
		}
		robot.put("nav_state", r.navState());
		root.put("robot", robot);
		if (m.contacts() != null) {
			List<Object> contacts = new ArrayList<>();
			for (String[] c : m.contacts()) {
				contacts.add(new ArrayList<>(List.of(c[0], c[1])));
			}
			root.put("contacts", contacts);
		}
		return root;
	}

	static Map<String, Object> missionTree(long seq, double t, String event, int task, double[] goal, String reason) {
		Map<String, Object> root = new LinkedHashMap<>();
		root.put("seq", seq);
		root.put("t", t);
		root.put("event", event);
		root.put("task_index", (long) task);
		root.put("goal", goal == null ? null : reals(goal));
		if (reason != null) {
			root.put("reason", reason);
		}
		return root;
	}

	private static List<Object> reals(double... v) {
		List<Object> out = new ArrayList<>();
		for (double d : v) {
			out.add(d);
		}
		return out;
	}

	static byte[] pack(Object tree) {
		try (MessageBufferPacker p = MessagePack.newDefaultBufferPacker()) {
			pack(p, tree);
			return p.toByteArray();
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}

	@SuppressWarnings("unchecked")
	private static void pack(MessageBufferPacker p, Object v) throws IOException {
		if (v == null) {
			p.packNil();
		} else if (v instanceof Raw raw) {
			p.writePayload(raw.bytes());
		} else if (v instanceof Map<?, ?> map) {
			p.packMapHeader(map.size());
			for (Map.Entry<?, ?> e : map.entrySet()) {
				pack(p, e.getKey());
				pack(p, e.getValue());
			}
		} else if (v instanceof List<?> list) {
			p.packArrayHeader(list.size());
			for (Object o : list) {
				pack(p, o);
			}
		} else if (v instanceof String s) {
			p.packString(s);
		} else if (v instanceof Double d) {
			p.packDouble(d);
		} else if (v instanceof Float f) {
			p.packFloat(f);
		} else if (v instanceof Long l) {
			p.packLong(l);
		} else if (v instanceof Integer i) {
			p.packInt(i);
		} else if (v instanceof Boolean b) {
			p.packBoolean(b);
		} else if (v instanceof byte[] b) {
			p.packBinaryHeader(b.length);
			p.writePayload(b);
		} else {
			throw new IllegalArgumentException(String.valueOf(v));
		}
	}

	// ---- mutations ----

	/** Every place of a tree: the container and the key (String for maps, Integer for lists). */
	private record Slot(Object container, Object key) {
	}

	private static void slots(Object v, List<Slot> out) {
		if (v instanceof Map<?, ?> map) {
			for (Object k : map.keySet()) {
				out.add(new Slot(map, k));
				slots(map.get(k), out);
			}
		} else if (v instanceof List<?> list) {
			for (int i = 0; i < list.size(); i++) {
				out.add(new Slot(list, i));
				slots(list.get(i), out);
			}
		}
	}

	@SuppressWarnings("unchecked")
	private static void set(Slot s, Object value) {
		if (s.container() instanceof Map<?, ?> m) {
			((Map<Object, Object>) m).put(s.key(), value);
		} else {
			((List<Object>) s.container()).set((Integer) s.key(), value);
		}
	}

	@SuppressWarnings("unchecked")
	private static Object deepCopy(Object v) {
		if (v instanceof Map<?, ?> m) {
			Map<Object, Object> out = new LinkedHashMap<>();
			m.forEach((k, x) -> out.put(k, deepCopy(x)));
			return out;
		}
		if (v instanceof List<?> l) {
			List<Object> out = new ArrayList<>();
			l.forEach(x -> out.add(deepCopy(x)));
			return out;
		}
		return v;
	}

	private static final byte[][] HUGE_HEADERS = {
		{ (byte) 0xdd, 0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff }, // array32 2^31-1
		{ (byte) 0xdd, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff }, // array32 2^32-1
		{ (byte) 0xdf, 0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff }, // map32
		{ (byte) 0xdf, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff },
		{ (byte) 0xdb, 0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff, 'a', 'b' }, // str32
		{ (byte) 0xdb, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff, 'a' },
		{ (byte) 0xc6, 0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff, 1, 2 }, // bin32
		{ (byte) 0xc9, 0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff, 1, 2 }, // ext32
		{ (byte) 0xdc, (byte) 0xff, (byte) 0xff }, // array16
		{ (byte) 0xcf, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff,
				(byte) 0xff }, // uint64 max
		{ (byte) 0xc1 }, // never used
	};

	private static final Object[] STRANGE = { Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, -0.0,
			Double.MAX_VALUE, Double.MIN_VALUE, 1e308, -1e308, Float.NaN, Long.MAX_VALUE, Long.MIN_VALUE, -1L, 0L,
			Integer.MAX_VALUE + 1L, "", "x", "\u0000", "tb3", "\uD83D\uDE00", true, false, null, new byte[] { 1, 2 },
			List.of(), Map.of(), };

	/** One mutation of a valid message tree: {name, bytes}. */
	static Object[] mutate(Map<String, Object> valid, Random r) {
		Object tree = deepCopy(valid);
		List<Slot> slots = new ArrayList<>();
		slots(tree, slots);
		Slot s = slots.get(r.nextInt(slots.size()));
		switch (r.nextInt(14)) {
		case 0 -> {
			set(s, STRANGE[r.nextInt(STRANGE.length)]);
			return new Object[] { "wrong-value", pack(tree) };
		}
		case 1 -> {
			double[] bad = { Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, -0.0 };
			for (Slot x : slots) { // every float of the message at once
				Object v = x.container() instanceof Map<?, ?> m ? m.get(x.key()) : ((List<?>) x.container()).get((Integer) x.key());
				if (v instanceof Double && r.nextInt(3) == 0) {
					set(x, bad[r.nextInt(bad.length)]);
				}
			}
			return new Object[] { "non-finite", pack(tree) };
		}
		case 2 -> {
			if (s.container() instanceof Map<?, ?> m) {
				m.remove(s.key());
			} else {
				((List<?>) s.container()).remove((int) (Integer) s.key());
			}
			return new Object[] { "missing", pack(tree) };
		}
		case 3 -> {
			@SuppressWarnings("unchecked")
			Map<String, Object> root = (Map<String, Object>) tree;
			root.put(r.nextBoolean() ? "extra" + r.nextInt(5) : "robot", STRANGE[r.nextInt(STRANGE.length)]);
			return new Object[] { "extra-field", pack(tree) };
		}
		case 4 -> {
			set(s, new Raw(HUGE_HEADERS[r.nextInt(HUGE_HEADERS.length)]));
			return new Object[] { "huge-length", pack(tree) };
		}
		case 5 -> {
			Object deep = 1L;
			int depth = 1 + r.nextInt(20_000);
			for (int i = 0; i < depth; i++) {
				deep = r.nextBoolean() ? new ArrayList<>(List.of(deep)) : new LinkedHashMap<>(Map.of("k", deep));
			}
			set(s, deep);
			return new Object[] { "deep", packDeep(tree) };
		}
		case 6 -> {
			@SuppressWarnings("unchecked")
			Map<String, Object> root = (Map<String, Object>) tree;
			// seqs that are old, negative or not a long; a huge seq is valid and ends the stream (every later one is
			// old), so it has its own test instead of poisoning this campaign
			Object[] seqs = { -1L, Long.MIN_VALUE, 0L, Math.max(0, (Long) root.get("seq") - 1), 1.5, "1",
					new Raw(HUGE_HEADERS[9]) };
			root.put("seq", seqs[r.nextInt(seqs.length)]);
			return new Object[] { "seq", pack(tree) };
		}
		case 7 -> {
			byte[] b = pack(tree);
			return new Object[] { "truncate", java.util.Arrays.copyOf(b, r.nextInt(b.length)) };
		}
		case 8, 9 -> {
			byte[] b = pack(tree);
			int n = 1 + r.nextInt(4);
			for (int i = 0; i < n; i++) {
				b[r.nextInt(b.length)] ^= (byte) (1 << r.nextInt(8));
			}
			return new Object[] { "flip", b };
		}
		case 10 -> {
			byte[] b = pack(tree);
			b[r.nextInt(b.length)] = (byte) r.nextInt(256);
			return new Object[] { "byte", b };
		}
		case 11 -> {
			byte[] b = new byte[r.nextInt(64)];
			r.nextBytes(b);
			return new Object[] { "random", b };
		}
		case 12 -> {
			@SuppressWarnings("unchecked")
			Map<String, Object> root = (Map<String, Object>) tree;
			List<Object> many = new ArrayList<>();
			int n = r.nextInt(20_000);
			for (int i = 0; i < n; i++) {
				many.add(i % 7 == 0 ? Double.NaN : (double) i);
			}
			Object robot = root.get("robot");
			if (robot instanceof Map<?, ?> m && r.nextBoolean()) {
				@SuppressWarnings("unchecked")
				Map<String, Object> rm = (Map<String, Object>) m;
				rm.put("laser_ranges", many);
			} else {
				set(s, many);
			}
			return new Object[] { "big-array", pack(tree) };
		}
		default -> {
			byte[] b = pack(tree);
			int cut = r.nextInt(b.length);
			byte[] out = new byte[b.length + 1];
			System.arraycopy(b, 0, out, 0, cut);
			out[cut] = (byte) r.nextInt(256);
			System.arraycopy(b, cut, out, cut + 1, b.length - cut);
			return new Object[] { "insert", out };
		}
		}
	}

	/** Packs without recursion limits of the JVM stack: deep trees are written iteratively where they are deep. */
	private static byte[] packDeep(Object tree) {
		try {
			return pack(tree);
		} catch (StackOverflowError e) {
			return new byte[] { (byte) 0x91, (byte) 0x91, (byte) 0x91 }; // truncated nesting instead
		}
	}

	// ---- feeding ----

	/** Feeds one message on the worker thread under the time limit; null if fine, else the failure. */
	public String feed(Monitor monitor, boolean state, byte[] bytes) {
		Future<?> f = worker.submit(() -> {
			if (state) {
				monitor.onStateBytes(bytes, 0, bytes.length);
			} else {
				monitor.onMissionBytes(bytes, 0, bytes.length);
			}
		});
		try {
			f.get(timeoutMillis, TimeUnit.MILLISECONDS);
			return null;
		} catch (TimeoutException e) {
			f.cancel(true);
			worker.shutdownNow();
			worker = newWorker();
			return "no return within " + timeoutMillis + " ms";
		} catch (ExecutionException e) {
			java.io.StringWriter w = new java.io.StringWriter();
			e.getCause().printStackTrace(new java.io.PrintWriter(w));
			return "threw " + w;
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			return "interrupted";
		}
	}

	static long totalProblems(Monitor m) {
		return m.guard().problems().values().stream().mapToLong(Long::longValue).sum();
	}

	/**
	 * Mutated messages, state and mission alternating with valid ones, into one monitor: each must return in
	 * time without throwing and be processed or counted under a named kind.
	 */
	public Result run(long seed, long maxMessages, double seconds) {
		Random random = new Random(seed);
		long deadline = System.nanoTime() + (long) (seconds * 1e9);
		List<StateMessage> trace = new ArrayList<>(TracesAccess.wallApproach());
		trace.addAll(TracesAccess.humanCrossing());
		List<String> failures = new ArrayList<>();
		long messages = 0;
		long processed = 0;
		String[] events = { "BEGIN", "TASK_START", "TASK_SUCCESS", "TASK_FAIL", "END" };
		try (TestRuns run = new TestRuns()) {
			Monitor m = run.monitor;
			long validSeq = 0;
			while (messages < maxMessages && System.nanoTime() < deadline) {
				boolean state = random.nextInt(3) != 0;
				Map<String, Object> valid;
				if (state) {
					StateMessage base = trace.get(random.nextInt(trace.size()));
					valid = stateTree(new StateMessage(validSeq, 1000 + validSeq * 0.05, base.full(), base.objects(),
							base.robot(), base.contacts()));
				} else {
					String event = events[random.nextInt(events.length)];
					valid = missionTree(validSeq, 1000 + validSeq * 0.05, event, event.startsWith("TASK") ? 1 : -1,
							event.startsWith("TASK") ? new double[] { 1.5, 2.5, 0 } : null,
							event.equals("TASK_FAIL") ? "timeout" : null);
				}
				boolean mutated = random.nextInt(4) != 0;
				Object[] msg = mutated ? mutate(valid, random) : new Object[] { "valid", pack(valid) };
				if (!mutated) {
					validSeq++;
				}
				long before = m.statesProcessed() + m.missionsProcessed();
				long problemsBefore = totalProblems(m);
				String failure = feed(m, state, (byte[]) msg[1]);
				messages++;
				if (failure != null) {
					failures.add("#" + messages + " " + msg[0] + " " + (state ? "state" : "mission") + ": " + failure);
					if (failure.startsWith("no return")) {
						break; // the monitor is owned by the stuck thread now
					}
					continue;
				}
				long done = m.statesProcessed() + m.missionsProcessed() - before;
				processed += done;
				if (done == 0 && totalProblems(m) == problemsBefore) {
					failures.add("#" + messages + " " + msg[0] + ": neither processed nor counted");
				}
			}
			for (String kind : m.guard().problems().keySet()) {
				if (!kind.matches("[a-z]+(-[a-z]+)*")) {
					failures.add("problem kind without a plain name: '" + kind + "'");
				}
			}
			return new Result(messages, processed, m.guard().problems(), failures);
		}
	}

	@Override
	public void close() {
		worker.shutdownNow();
	}

	/** {@code --seconds N --seed S [--messages N] [--timeout-ms N]}: a longer campaign; exit 1 on failures. */
	public static void main(String[] args) {
		double seconds = 60;
		long seed = System.nanoTime();
		long messages = Long.MAX_VALUE;
		long timeout = 5_000;
		for (int i = 0; i + 1 < args.length; i += 2) {
			switch (args[i]) {
			case "--seconds" -> seconds = Double.parseDouble(args[i + 1]);
			case "--seed" -> seed = Long.parseLong(args[i + 1]);
			case "--messages" -> messages = Long.parseLong(args[i + 1]);
			case "--timeout-ms" -> timeout = Long.parseLong(args[i + 1]);
			default -> throw new IllegalArgumentException("unknown option " + args[i]);
			}
		}
		try (WireFuzzer fuzzer = new WireFuzzer(timeout)) {
			Runtime rt = Runtime.getRuntime();
			Result r = fuzzer.run(seed, messages, seconds);
			System.gc();
			System.out.println("seed " + seed + ": " + r.messages() + " messages, " + r.processed() + " processed, "
					+ r.failures().size() + " failures, heap used " + (rt.totalMemory() - rt.freeMemory()) / (1 << 20)
					+ " MB of max " + rt.maxMemory() / (1 << 20) + " MB; problems " + r.problems());
			r.failures().stream().limit(50).forEach(System.out::println);
			System.exit(r.failures().isEmpty() ? 0 : 1);
		}
	}
}
