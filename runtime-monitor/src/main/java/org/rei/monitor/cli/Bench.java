/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.cli;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.rei.monitor.config.MonitorSpec;
import org.rei.monitor.config.World;
import org.rei.monitor.engine.DrlSources;
import org.rei.monitor.pipeline.Monitor;
import org.rei.monitor.replay.Recording;
import org.rei.monitor.signals.SignalPublisher;

/**
 * Throughput benchmark of the whole pipeline without a router (used by benchmarks/monitor_throughput.sh):
 * synthesises a world of N obstacles of which 50 move (humans on circles) and a robot weaving through them, encodes
 * a state stream in the wire layout (20 Hz, a full frame with every static obstacle each simulated second), and
 * feeds it message by message: decode, EMF update, geometry, queries, transition rules, signals.
 * Usage: {@code java -cp rei-monitor.jar org.rei.monitor.cli.Bench OBJECTS STATES [WARMUP]}.
 */
public final class Bench {

	private static final int MOVING = 50;
	private static final double RATE = 20;

	private Bench() {
	}

	public static void main(String[] args) throws IOException {
		int objects = Integer.parseInt(args[0]);
		int states = Integer.parseInt(args[1]);
		int warmup = args.length > 2 ? Integer.parseInt(args[2]) : Math.min(states / 4, 5000);
		int side = (int) Math.ceil(Math.sqrt(objects - MOVING));
		double pitch = 1.0;
		World world = world(objects, side, pitch);
		MonitorSpec spec = new MonitorSpec("Bench", "tb3", 0.25, 0.01, Map.of(), List.of());
		List<DrlSources.Source> rules = new ArrayList<>(DrlSources.packaged(DrlSources.QUERIES));
		rules.addAll(DrlSources.packaged(DrlSources.RULES));
		Recording stream = Recording.of(stream(world, side, pitch, warmup + states));
		SignalPublisher signals = new SignalPublisher();
		try (Monitor m = new Monitor("bench", world, spec, rules, signals, System.err::println, null)) {
			long start = System.nanoTime();
			long[] lat = new long[stream.size()];
			long[] sig = new long[stream.size()];
			long[] cpu = new long[stream.size()];
			java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
			for (int i = 0; i < stream.size(); i++) {
				long c0 = threads.getCurrentThreadCpuTime();
				long s0 = System.nanoTime();
				m.onStateBytes(stream.data(), stream.offset(i), stream.length(i));
				lat[i] = System.nanoTime() - s0;
				cpu[i] = threads.getCurrentThreadCpuTime() - c0;
				sig[i] = signals.count();
			}
			double all = (System.nanoTime() - start) / 1e9;
			if (System.getProperty("bench.slow") != null) {
				for (int i = warmup; i < lat.length; i++) {
					if (lat[i] > 1_000_000) {
						System.out.printf("slow step %d (k mod 20 = %d): %.2f ms, signals %d%n", i, i % 20, lat[i] / 1e6, sig[i] - sig[i - 1]);
					}
				}
			}
			long[] measured = Arrays.copyOfRange(lat, warmup, lat.length);
			double seconds = Arrays.stream(measured).sum() / 1e9;
			Arrays.sort(measured);
			System.out.printf("objects=%d moving=%d states=%d warmup=%d stream=%.1f MB full_frame_every=%d%n", objects,
					MOVING, states, warmup, stream.data().length / 1e6, (int) RATE);
			System.out.printf("RESULT objects=%d updates_per_s=%.0f p50_us=%.1f p90_us=%.1f p99_us=%.1f max_us=%.1f "
					+ "(all %d states incl. warm-up: %.2f s)%n", objects, measured.length / seconds, pct(measured, 0.50),
					pct(measured, 0.90), pct(measured, 0.99), measured[measured.length - 1] / 1e3, lat.length, all);
			// CPU time of the pipeline thread per update: what one core costs, without other processes' preemption
			long[] cpuMeasured = Arrays.copyOfRange(cpu, warmup, cpu.length);
			double cpuSeconds = Arrays.stream(cpuMeasured).sum() / 1e9;
			Arrays.sort(cpuMeasured);
			System.out.printf("CPU    objects=%d updates_per_cpu_s=%.0f cpu_p50_us=%.1f cpu_p99_us=%.1f%n", objects,
					cpuMeasured.length / cpuSeconds, pct(cpuMeasured, 0.50), pct(cpuMeasured, 0.99));
			System.out.printf("signals=%d nearby_facts_at_end=%d facts=%d static_entries_skipped=%d problems=%s%n",
					signals.count(), m.engine().nearbyCount(), m.engine().factCount(), m.staticEntriesSkipped(),
					m.guard().problems());
		}
	}

	private static double pct(long[] sorted, double p) {
		return sorted[Math.min(sorted.length - 1, (int) (sorted.length * p))] / 1e3;
	}

	private static World world(int objects, int side, double pitch) {
		List<World.WorldObject> list = new ArrayList<>();
		for (int i = 0; i < objects - MOVING; i++) {
			double x = (i % side + 0.5) * pitch;
			double y = (i / side + 0.5) * pitch;
			list.add(new World.WorldObject("box" + i, "STATIC", "Box", "BOX", new double[] { 0.3, 0.3, 0.5 },
					new double[] { x, y, 0.25, 0.3 * (i % 7) }, null));
		}
		for (int h = 0; h < MOVING; h++) {
			list.add(new World.WorldObject("human" + h, "HUMAN", "Human", "CYLINDER", new double[] { 0.5, 0.5, 1.7 },
					human(h, 0, side, pitch), null));
		}
		World.WorldRobot robot = new World.WorldRobot("tb3", "Waffle", "BOX", new double[] { 0.281, 0.306, 0.141 },
				robot(0, side, pitch), null, 0.12, 3.5);
		return new World("Bench", "Grid", 1.0, List.of(), list, robot);
	}

	/** Humans walk circles of 0.5 m around grid-cell corners, spread over the room. */
	private static double[] human(int h, double t, int side, double pitch) {
		double cx = ((h * 7) % side + 1) * pitch;
		double cy = ((h * 13) % side + 1) * pitch;
		double a = 0.8 * t + h;
		return new double[] { cx + 0.5 * Math.cos(a), cy + 0.5 * Math.sin(a), 0.85, a + Math.PI / 2 };
	}

	/** The robot weaves along the grid's lanes (between obstacles) at ~0.25 m/s: it passes close to many. */
	private static double[] robot(double t, int side, double pitch) {
		double span = Math.max(2, side - 2) * pitch;
		double x = pitch + span / 2 * (1 + Math.sin(0.25 * t / Math.max(1, span / 4)));
		double y = pitch * (1 + 0.5 * Math.sin(0.9 * t)) + span / 2 * (1 + Math.sin(0.13 * t / Math.max(1, span / 4)));
		return new double[] { x, y, 0, 0.9 * t };
	}

	private static byte[] stream(World world, int side, double pitch, int n) throws IOException {
		MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
		List<World.WorldObject> statics = world.objects().stream().filter(o -> !o.moves()).toList();
		for (int k = 0; k < n; k++) {
			double t = k / RATE;
			boolean full = k % (int) RATE == 0;
			p.packMapHeader(full ? 6 : 5);
			p.packString("seq").packLong(k);
			p.packString("t").packDouble(t);
			if (full) {
				p.packString("full").packBoolean(true);
			}
			p.packString("objects").packArrayHeader(MOVING + (full ? statics.size() : 0));
			for (int h = 0; h < MOVING; h++) {
				object(p, "human" + h, "HUMAN", human(h, t, side, pitch));
			}
			if (full) {
				for (World.WorldObject o : statics) {
					object(p, o.name(), o.category(), o.pose());
				}
			}
			double[] r = robot(t, side, pitch);
			p.packString("robot").packMapHeader(6);
			p.packString("name").packString("tb3");
			p.packString("pose").packArrayHeader(4).packDouble(r[0]).packDouble(r[1]).packDouble(0).packDouble(r[3]);
			p.packString("twist").packArrayHeader(3).packDouble(0.25).packDouble(0).packDouble(0.9);
			p.packString("odom").packArrayHeader(3).packDouble(r[0]).packDouble(r[1]).packDouble(r[3]);
			p.packString("laser_min").packDouble(0.3 + 0.2 * Math.sin(t));
			p.packString("nav_state").packString("ACTIVE");
			p.packString("contacts").packArrayHeader(0);
		}
		return p.toByteArray();
	}

	private static void object(MessageBufferPacker p, String name, String category, double[] pose) throws IOException {
		p.packMapHeader(4);
		p.packString("name").packString(name);
		p.packString("type").packString(category);
		p.packString("pose").packArrayHeader(4).packDouble(pose[0]).packDouble(pose[1]).packDouble(pose[2])
				.packDouble(pose[3]);
		p.packString("twist").packArrayHeader(3).packDouble(0).packDouble(0).packDouble(0);
	}
}
