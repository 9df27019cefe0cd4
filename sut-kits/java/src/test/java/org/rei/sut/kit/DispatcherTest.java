/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.rei.sut.kit.MessagesTest.HELLO;
import static org.rei.sut.kit.MessagesTest.SCAN;
import static org.rei.sut.kit.MessagesTest.msgpack;
import static org.rei.sut.kit.MessagesTest.tick;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

import org.junit.jupiter.api.Test;

/** Callbacks in order, and what reaches the simulation in which order. */
class DispatcherTest {

	private final List<String> sent = new ArrayList<>();
	private final List<Tick> ticks = new ArrayList<>();
	private final List<String> calls = new ArrayList<>();
	private final List<Goal> goals = new ArrayList<>();

	/** A SUT whose onTick is {@code body}, recording every callback. */
	private Dispatcher dispatcher(Function<Tick, Command> body) throws Exception {
		SystemUnderTest sut = new SystemUnderTest() {
			@Override
			public void onStart(Session session) {
				calls.add("start " + session.runId());
			}

			@Override
			public void onGoal(Goal goal) {
				calls.add("goal " + goal.id());
				goals.add(goal);
			}

			@Override
			public void onCancel(Goal goal) {
				calls.add("cancel " + goal.id() + " " + goal.status());
			}

			@Override
			public Command onTick(Tick tick) {
				ticks.add(tick);
				return body.apply(tick);
			}

			@Override
			public void onEnd(String reason) {
				calls.add("end " + reason);
			}
		};
		Dispatcher d = new Dispatcher(sut, (name, payload) -> sent.add(name + " " + payload));
		d.hello(msgpack(HELLO));
		return d;
	}

	private static String goal(int id) {
		return "{\"goal_id\": " + id + ", \"t\": 0.0, \"pose\": [4.5, 0.5, 0.0], \"tolerance\": 0.2}";
	}

	@Test
	void aScanlessTickKeepsTheLastScan() throws Exception {
		Dispatcher d = dispatcher(t -> Command.STOP);
		d.dispatch("tick", msgpack(tick(0, "null")));
		d.dispatch("tick", msgpack(tick(1, SCAN)));
		d.dispatch("tick", msgpack(tick(2, "null")));
		assertEquals(null, ticks.get(0).scan());
		assertTrue(ticks.get(1).scanIsNew());
		assertSame(ticks.get(1).scan(), ticks.get(2).scan());
		assertFalse(ticks.get(2).scanIsNew());
		assertEquals(List.of("command {\"tick\":0,\"v\":0.0,\"w\":0.0}", "command {\"tick\":1,\"v\":0.0,\"w\":0.0}",
				"command {\"tick\":2,\"v\":0.0,\"w\":0.0}"), sent);
	}

	@Test
	void aChangedStatusGoesBeforeTheCommandOfItsTick() throws Exception {
		Dispatcher d = dispatcher(t -> {
			if (t.number() == 2) {
				t.goal().active("half way");
			} else if (t.number() >= 4) {
				t.goal().succeeded("there");
			} else {
				t.goal().active(t.goal().text()); // unchanged: nothing to publish
			}
			return new Command(0.1, 0);
		});
		d.dispatch("goal", msgpack(goal(0)));
		for (int k = 0; k < 6; k++) {
			d.dispatch("tick", msgpack(tick(k, "null")));
		}
		assertEquals(List.of("status {\"goal_id\":0,\"status\":\"ACTIVE\"}", // accepted with the goal
				"command {\"tick\":0,\"v\":0.1,\"w\":0.0}", "command {\"tick\":1,\"v\":0.1,\"w\":0.0}",
				"status {\"goal_id\":0,\"status\":\"ACTIVE\",\"text\":\"half way\"}",
				"command {\"tick\":2,\"v\":0.1,\"w\":0.0}", "command {\"tick\":3,\"v\":0.1,\"w\":0.0}",
				"status {\"goal_id\":0,\"status\":\"SUCCEEDED\",\"text\":\"there\"}",
				"command {\"tick\":4,\"v\":0.1,\"w\":0.0}", "command {\"tick\":5,\"v\":0.1,\"w\":0.0}"), sent);
	}

	@Test
	void cancelsTheCurrentGoalOnlyAndForgetsReplacedOnes() throws Exception {
		Dispatcher d = dispatcher(t -> {
			if (t.number() == 1) {
				goals.get(0).aborted("a report on the replaced goal"); // not published
				t.goal().aborted("stuck");
			}
			return Command.STOP;
		});
		d.dispatch("goal", msgpack(goal(0)));
		d.dispatch("cancel", msgpack("{\"goal_id\": 5, \"t\": 1.0}")); // not ours: ignored
		d.dispatch("cancel", msgpack("{\"goal_id\": 0, \"t\": 1.0}"));
		d.dispatch("goal", msgpack(goal(1)));
		d.dispatch("tick", msgpack(tick(0, "null")));
		d.dispatch("tick", msgpack(tick(1, "null")));
		assertEquals(List.of("start r1", "goal 0", "cancel 0 CANCELLED", "goal 1"), calls);
		assertSame(goals.get(1), ticks.get(0).goal());
		assertEquals(List.of("status {\"goal_id\":0,\"status\":\"ACTIVE\"}",
				"status {\"goal_id\":0,\"status\":\"CANCELLED\",\"text\":\"cancelled by the client\"}",
				"status {\"goal_id\":1,\"status\":\"ACTIVE\"}",
				"command {\"tick\":0,\"v\":0.0,\"w\":0.0}",
				"status {\"goal_id\":1,\"status\":\"ABORTED\",\"text\":\"stuck\"}",
				"command {\"tick\":1,\"v\":0.0,\"w\":0.0}"), sent);
	}

	@Test
	void statusTextIsCutToTheProtocolLimit() {
		Goal g = new Goal(0, 0, new Pose(0, 0, 0), 0.2);
		g.aborted("x".repeat(5000));
		assertEquals(Goal.MAX_TEXT, g.text().length());
	}

	@Test
	void endCallsOnEndAndStops() throws Exception {
		Dispatcher d = dispatcher(t -> Command.STOP);
		assertTrue(d.dispatch("end", msgpack("{\"t\": 3.0, \"reason\": \"mission ended\"}")));
		assertEquals("end mission ended", calls.get(calls.size() - 1));
	}

	@Test
	void aThrowingCallbackStopsWithExitCode1() throws Exception {
		Dispatcher d = dispatcher(t -> {
			throw new IllegalStateException("boom");
		});
		SutException e = assertThrows(SutException.class, () -> d.dispatch("tick", msgpack(tick(3, "null"))));
		assertEquals(SutClient.EXIT_CALLBACK, e.exitCode());
		assertTrue(e.getMessage().startsWith("onTick failed at tick 3 (t=0.300 s)"), e.getMessage());
		assertEquals("boom", e.getCause().getMessage());
		assertTrue(sent.isEmpty());
	}

	@Test
	void aMissingCommandIsAnError() throws Exception {
		Dispatcher d = dispatcher(t -> null);
		assertEquals(SutClient.EXIT_CALLBACK,
				assertThrows(SutException.class, () -> d.dispatch("tick", msgpack(tick(0, "null")))).exitCode());
	}

	@Test
	void nothingBeforeHello() {
		Dispatcher d = new Dispatcher(t -> Command.STOP, (name, payload) -> sent.add(name));
		assertEquals(SutClient.EXIT_CONNECTION,
				assertThrows(SutException.class, () -> d.dispatch("tick", msgpack(tick(0, "null")))).exitCode());
	}
}
