/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import java.util.Map;
import java.util.TreeMap;
import java.util.function.Consumer;

/**
 * Bad input never stops the monitor: every problem is counted by kind and logged the first time its kind occurs
 * (a stream of identical problems must not flood the log). Also tracks {@code seq} per topic: an old or repeated
 * seq is out of order (skipped), a jump forward is a gap (reported, then the message is used).
 */
public final class InputGuard {

	private final Map<String, Long> problems = new TreeMap<>();
	private final Consumer<String> log;

	public InputGuard(Consumer<String> log) {
		this.log = log;
	}

	/** Counts a problem of {@code kind}; logs it if it is the first of its kind. */
	public void problem(String kind, String detail) {
		long n = problems.merge(kind, 1L, Long::sum);
		if (n == 1) {
			log.accept("skipped a message (" + kind + "): " + detail + " - further '" + kind + "' problems are only counted");
		}
	}

	public Map<String, Long> problems() {
		return Map.copyOf(problems);
	}

	public long count(String kind) {
		return problems.getOrDefault(kind, 0L);
	}

	/** The sequence of one topic. */
	public static final class Sequence {
		private long next;
		private double lastT = Double.NEGATIVE_INFINITY;

		/** How many messages are missing before {@code seq}: 0 in order, > 0 a gap, < 0 old or repeated. */
		public long missingBefore(long seq) {
			return seq - next;
		}

		public double lastT() {
			return lastT;
		}

		public void accept(long seq, double t) {
			next = seq + 1;
			lastT = t;
		}
	}
}
