/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wamp;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import org.rei.monitor.signals.Signal;

/**
 * Signals on their way to the router, at least once and in {@code seq} order. A signal stays here from its
 * emission until the router acknowledges its publication: while disconnected it waits, and on every
 * (re)connection everything unacknowledged is published again, in seq order, before any newer signal. A receiver
 * drops a duplicate by its seq (the acknowledgement of a delivered signal may die with the connection).
 * <p>
 * Relies on the transport's order, which jawampa's one thread gives: a publication lost to a disconnection is reported
 * after {@link #disconnected()}, and one requested before a disconnection never goes out in a later session (else a
 * signal lost while this outbox believes it is connected would wait for the next connection, or one could overtake
 * the resent ones).
 * Thread-safe: the pipeline offers, the WAMP thread reports connections and outcomes.
 */
public final class SignalOutbox {

	/** How one publication ended. */
	public enum Outcome {
		/** The router has it. */
		ACKNOWLEDGED,
		/** The connection went away first: publish it again after reconnecting. */
		LOST,
		/** The router refused it (e.g. not authorised): sending it again would not help, it is dropped. */
		REFUSED
	}

	/** Sends one signal and reports its outcome once (possibly before returning). */
	@FunctionalInterface
	public interface Transport {
		void publish(Signal signal, Consumer<Outcome> done);
	}

	private final Transport transport;
	private final TreeMap<Long, Signal> unacknowledged = new TreeMap<>();
	private boolean connected;
	private long refused;

	public SignalOutbox(Transport transport) {
		this.transport = transport;
	}

	/** A new signal: published now if connected, else kept for the next connection. */
	public synchronized void offer(Signal s) {
		unacknowledged.put(s.seq(), s);
		if (connected) {
			send(s);
		}
	}

	/** A session began: publishes every unacknowledged signal in seq order; returns how many. */
	public synchronized int connected() {
		connected = true;
		// a copy: a transport may report an outcome at once, which changes the map
		List<Signal> again = new ArrayList<>(unacknowledged.values());
		for (Signal s : again) {
			send(s);
		}
		return again.size();
	}

	/** The session is gone: new signals wait for the next one. */
	public synchronized void disconnected() {
		connected = false;
	}

	private void send(Signal s) {
		transport.publish(s, outcome -> done(s, outcome));
	}

	private synchronized void done(Signal s, Outcome outcome) {
		switch (outcome) {
		case ACKNOWLEDGED -> unacknowledged.remove(s.seq());
		case REFUSED -> {
			if (unacknowledged.remove(s.seq()) != null) {
				refused++;
			}
		}
		case LOST -> {
			// kept: connected() sends it again
		}
		}
		notifyAll();
	}

	/** Signals not acknowledged yet (waiting or on the wire). */
	public synchronized int pending() {
		return unacknowledged.size();
	}

	/** Signals the router refused (dropped). */
	public synchronized long refused() {
		return refused;
	}

	/** Waits until every signal is acknowledged (or dropped) or the time is up; true if none is pending. */
	public synchronized boolean awaitEmpty(long millis) throws InterruptedException {
		long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
		while (!unacknowledged.isEmpty()) {
			long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
			if (left <= 0) {
				return false;
			}
			wait(left);
		}
		return true;
	}
}
