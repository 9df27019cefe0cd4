/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import java.util.Locale;
import java.util.Objects;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The SUT's side of the protocol without the transport: decodes what the simulation sent, calls the callbacks and
 * publishes what they decided, in the order docs/sut.md requires (a changed status before the command of its tick).
 * Not thread-safe: the client feeds it from one thread.
 */
final class Dispatcher {

	/** Where outgoing payloads go: {@code name} is the URI's last part ({@code command}, {@code status}). */
	interface Outbox {
		void publish(String name, ObjectNode payload);
	}

	private final SystemUnderTest sut;
	private final Outbox outbox;
	private Session session;
	private Goal goal;
	private Scan scan;
	/** What was last published for {@link #goal}: a report is sent only when it differs. */
	private GoalStatus sentStatus;
	private String sentText;

	Dispatcher(SystemUnderTest sut, Outbox outbox) {
		this.sut = Objects.requireNonNull(sut, "sut");
		this.outbox = outbox;
	}

	/** The session, once {@code hello} was answered. */
	Session session() {
		return session;
	}

	/** Handles one event of the topic {@code name}; true if it was {@code end}. */
	boolean dispatch(String name, JsonNode payload) {
		if (session == null) {
			throw new SutException(SutClient.EXIT_CONNECTION, "the simulation sent " + name + " before hello's answer");
		}
		switch (name) {
		case "goal" -> goal(payload);
		case "cancel" -> cancel(payload);
		case "tick" -> tick(payload);
		case "end" -> {
			String reason = Messages.end(payload);
			call("onEnd", "", () -> sut.onEnd(reason));
			return true;
		}
		default -> throw new IllegalArgumentException("unknown topic " + name);
		}
		return false;
	}

	void hello(JsonNode result) {
		if (session != null) {
			return; // a second answer (hello called again) is the same: start only once
		}
		Session s = Messages.session(result);
		session = s;
		call("onStart", "", () -> sut.onStart(s));
	}

	private void goal(JsonNode payload) {
		Goal g = Messages.goal(payload);
		goal = g;
		sentStatus = null;
		sentText = null;
		call("onGoal", at(g.t()), () -> sut.onGoal(g));
		publishStatus();
	}

	private void cancel(JsonNode payload) {
		int id = Messages.cancel(payload);
		Goal g = goal;
		if (g == null || g.id() != id) {
			return; // not the goal we work on: nothing to withdraw
		}
		g.cancelled("cancelled by the client"); // the mission executor is the action's client
		call("onCancel", "", () -> sut.onCancel(g));
		publishStatus();
	}

	private void tick(JsonNode payload) {
		Messages.TickMessage m = Messages.tick(payload);
		if (m.scan() != null) {
			scan = m.scan();
		}
		Tick tick = new Tick(m.tick(), m.t(), m.odom(), m.twist(), scan, m.scan() != null, goal);
		Command[] command = new Command[1];
		String where = String.format(Locale.ROOT, " at tick %d (t=%.3f s)", m.tick(), m.t());
		call("onTick", where, () -> command[0] = sut.onTick(tick));
		if (command[0] == null) {
			throw new SutException(SutClient.EXIT_CALLBACK, "onTick returned null" + where + ": return a Command");
		}
		publishStatus(); // before the command: the simulation reads it from the next tick on
		outbox.publish(SutClient.COMMAND, Messages.command(m.tick(), command[0]));
	}

	private void publishStatus() {
		Goal g = goal;
		if (g == null || (g.status() == sentStatus && Objects.equals(g.text(), sentText))) {
			return;
		}
		sentStatus = g.status();
		sentText = g.text();
		outbox.publish(SutClient.STATUS, Messages.status(g.id(), sentStatus, sentText));
	}

	private interface Callback {
		void run() throws Exception;
	}

	/** Runs a user callback; whatever it throws stops the SUT with exit code 1 and the cause's stack trace. */
	private static void call(String name, String where, Callback callback) {
		try {
			callback.run();
		} catch (Exception | Error e) {
			throw new SutException(SutClient.EXIT_CALLBACK, name + " failed" + where + ": " + e, e);
		}
	}

	private static String at(double t) {
		return String.format(Locale.ROOT, " at t=%.3f s", t);
	}
}
