/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.kie.api.runtime.KieSession;
import org.kie.api.time.SessionPseudoClock;
import org.rei.vepl.compiler.CompiledRules;
import org.rei.vepl.compiler.DrlTarget;
import org.rei.vepl.compiler.VeplLoader;
import org.rei.vepl.runtime.QueryEvent;

/**
 * Complex-event throughput (benchmarks/vepl_throughput.sh): the default patterns plus three user patterns (20 rules)
 * on a stream of query events from random walks of several robots through the geometric and laser states, with
 * per-object query events no pattern names mixed in, 20 Hz simulation time. Each event is inserted and the rules
 * fired on its own, so the latency is per event. Prints events/s, p50/p99/max latency and signals.
 */
public final class VeplBench {

	private static final String USER = """
			complexEvent hitSoonAfterClose() { as (atomicCloseToObject -> atomicCollisionToObject)[500] context chronicle }
			complexEvent bothSensorsClose() { as (atomicCloseToObject AND laserSensesClose)[200] context immediate }
			complexEvent closeWithoutLaser() { as (atomicCloseToObject -> NOT laserSensesClose)[300] context immediate }
			signal SIG_USER_1
			signal SIG_USER_2
			signal SIG_USER_3
			rule "user 1" on hitSoonAfterClose emits SIG_USER_1
			rule "user 2" on bothSensorsClose emits SIG_USER_2
			rule "user 3" on closeWithoutLaser emits SIG_USER_3
			""";

	private static final String[][] FAMILIES = { { "robotFar", "robotClose", "robotInCollision" },
			{ "laserSensesNothingClose", "laserSensesCloseness", "laserSensesCollision" } };

	private VeplBench() {
	}

	public static void main(String[] args) throws Exception {
		int robots = args.length > 0 ? Integer.parseInt(args[0]) : 10;
		int measured = args.length > 1 ? Integer.parseInt(args[1]) : 1_000_000;
		List<VeplLoader.Source> sources = new ArrayList<>(DefaultPatterns.sources());
		sources.add(new VeplLoader.Source("user.vepl", USER));
		CompiledRules rules = VeplLoader.compile(sources, Cep.QUERIES, DrlTarget.MONITOR);
		long ruleCount = rules.files().stream().mapToLong(f -> f.text().lines().filter(l -> l.startsWith("rule ")).count())
				.sum();
		KieSession session = Cep.build(rules);
		RecordingSink sink = new RecordingSink();
		session.setGlobal("signals", sink);
		SessionPseudoClock clock = session.getSessionClock();
		Random random = new Random(42);
		int[][] state = new int[robots][2];
		long t = 0;
		int warmup = measured / 5;
		long[] latency = new long[measured];
		int n = 0;
		long start = 0;
		ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
		long cpuStart = 0;
		long signalsBefore = 0;
		while (n < measured) {
			t += 50;
			clock.advanceTime(50, TimeUnit.MILLISECONDS);
			for (int r = 0; r < robots; r++) {
				String subject = "r" + r;
				double at = t / 1000.0;
				List<QueryEvent> events = new ArrayList<>();
				for (int f = 0; f < 2; f++) {
					if (random.nextInt(4) == 0) {
						int to = (state[r][f] + 1 + random.nextInt(2)) % 3;
						events.add(new QueryEvent(FAMILIES[f][state[r][f]], QueryEvent.Kind.LOST, subject, "x", 0, at));
						events.add(new QueryEvent(FAMILIES[f][to], QueryEvent.Kind.FOUND, subject, "x", 0, at));
						state[r][f] = to;
					}
				}
				if (random.nextInt(2) == 0) { // a per-object query that no pattern names
					events.add(new QueryEvent("closeToObject", random.nextBoolean() ? QueryEvent.Kind.FOUND
							: QueryEvent.Kind.LOST, subject, "o" + random.nextInt(5), 0, at));
				}
				for (QueryEvent e : events) {
					long s = System.nanoTime();
					session.insert(e);
					session.fireAllRules();
					long d = System.nanoTime() - s;
					if (warmup > 0) {
						if (--warmup == 0) {
							start = System.nanoTime();
							cpuStart = cpu.getCurrentThreadCpuTime();
							signalsBefore = sink.emitted.size();
						}
					} else if (n < measured) {
						latency[n++] = d;
					}
				}
			}
			if (sink.emitted.size() > 100_000) {
				signalsBefore -= sink.emitted.size();
				sink.emitted.clear();
			}
		}
		double seconds = (System.nanoTime() - start) / 1e9;
		double cpuSeconds = (cpu.getCurrentThreadCpuTime() - cpuStart) / 1e9;
		long[] sorted = latency.clone();
		Arrays.sort(sorted);
		System.out.printf("rules %d, robots %d, query events %d in %.2f s of wall time (%.1f s simulated)%n", ruleCount,
				robots, measured, seconds, t / 1000.0);
		System.out.printf("throughput %.0f query events/s (wall clock)%n", measured / seconds);
		System.out.printf("cpu %.0f query events per CPU-second of the benchmark thread%n", measured / cpuSeconds);
		System.out.printf("latency per event: p50 %.1f us, p99 %.1f us, max %.1f us%n", sorted[measured / 2] / 1e3,
				sorted[(int) (measured * 0.99)] / 1e3, sorted[measured - 1] / 1e3);
		System.out.printf("signals %d, facts in session at end %d%n", sink.emitted.size() - signalsBefore,
				session.getFactCount());
		session.dispose();
	}
}
