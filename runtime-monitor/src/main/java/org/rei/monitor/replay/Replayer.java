/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.replay;

import java.util.ArrayList;
import java.util.List;

import org.rei.monitor.pipeline.Monitor;
import org.rei.monitor.wire.MalformedMessageException;
import org.rei.monitor.wire.MissionMessage;
import org.rei.monitor.wire.StateMessage;
import org.rei.monitor.wire.WireDecoder;

/**
 * Feeds recorded state and mission streams through the monitor at full speed, without a router: the streams are
 * merged by simulation time in the order the sim-adapter publishes them, so a replay sees what a live monitor saw.
 * A mission event goes after the state message of the same time: the simulation loop publishes the state of a
 * step when the step ends and the mission executor's events of time t at the start of the next step, decided from
 * the pose at t (the state just sent). Returns per-state latencies (nanoseconds, decode to signals) for the
 * benchmark.
 */
public final class Replayer {

	private Replayer() {
	}

	public static long[] replay(Monitor monitor, Recording states, Recording missions) {
		List<MissionMessage> pending = new ArrayList<>();
		if (missions != null) {
			for (int i = 0; i < missions.size(); i++) {
				try {
					pending.add(WireDecoder.decodeMission(missions.data(), missions.offset(i), missions.length(i)));
				} catch (MalformedMessageException e) {
					monitor.guard().problem(e.kind(), e.getMessage());
				}
			}
			if (missions.truncated()) {
				monitor.guard().problem("truncated-recording", "the mission recording ends inside a message");
			}
		}
		int next = 0;
		long[] latency = new long[states.size()];
		for (int i = 0; i < states.size(); i++) {
			long start = System.nanoTime();
			StateMessage m = monitor.decodeState(states.data(), states.offset(i), states.length(i));
			if (m == null) { // counted by the monitor
				latency[i] = System.nanoTime() - start;
				continue;
			}
			while (next < pending.size() && pending.get(next).t() < m.t()) {
				monitor.onMission(pending.get(next++));
			}
			monitor.onState(m);
			latency[i] = System.nanoTime() - start;
		}
		while (next < pending.size()) {
			monitor.onMission(pending.get(next++));
		}
		if (states.truncated()) {
			monitor.guard().problem("truncated-recording", "the state recording ends inside a message");
		}
		return latency;
	}
}
