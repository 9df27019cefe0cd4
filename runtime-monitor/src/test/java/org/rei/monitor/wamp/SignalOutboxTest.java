/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wamp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import org.junit.jupiter.api.Test;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.wamp.SignalOutbox.Outcome;

/** The outbox's promise: every signal reaches the router at least once, and each session sees them in seq order. */
class SignalOutboxTest {

	private static Signal signal(long seq) {
		return new Signal(seq, seq * 0.05, "SIG_TEST", "tb3", "wall", 0.1);
	}

	/** Remembers every publication; the test decides each outcome. */
	private static final class Recorder implements SignalOutbox.Transport {
		final List<Long> sent = new ArrayList<>();
		final List<Consumer<Outcome>> outcomes = new ArrayList<>();

		@Override
		public void publish(Signal s, Consumer<Outcome> done) {
			sent.add(s.seq());
			outcomes.add(done);
		}

		void settle(int from, Outcome outcome) {
			for (Consumer<Outcome> done : new ArrayList<>(outcomes.subList(from, outcomes.size()))) {
				done.accept(outcome);
			}
		}
	}

	@Test
	void publishesAtOnceWhileConnected() {
		Recorder r = new Recorder();
		SignalOutbox outbox = new SignalOutbox(r);
		assertEquals(0, outbox.connected());
		outbox.offer(signal(0));
		outbox.offer(signal(1));
		assertEquals(List.of(0L, 1L), r.sent);
		assertEquals(2, outbox.pending());
		r.settle(0, Outcome.ACKNOWLEDGED);
		assertEquals(0, outbox.pending());
	}

	@Test
	void keepsSignalsWhileDisconnectedAndSendsThemFirstOnReconnecting() {
		Recorder r = new Recorder();
		SignalOutbox outbox = new SignalOutbox(r);
		outbox.connected();
		outbox.offer(signal(0));
		r.settle(0, Outcome.ACKNOWLEDGED);
		outbox.offer(signal(1));
		outbox.offer(signal(2)); // both on the wire when the connection dies
		outbox.disconnected();
		r.settle(1, Outcome.LOST);
		outbox.offer(signal(3));
		outbox.offer(signal(4)); // emitted while disconnected: kept
		assertEquals(List.of(0L, 1L, 2L), r.sent);
		assertEquals(4, outbox.pending());

		assertEquals(4, outbox.connected());
		outbox.offer(signal(5));
		assertEquals(List.of(0L, 1L, 2L, 1L, 2L, 3L, 4L, 5L), r.sent, "the unacknowledged ones again, in seq order, then the new one");
		r.settle(3, Outcome.ACKNOWLEDGED);
		assertEquals(0, outbox.pending());
	}

	@Test
	void sendsAgainOnlyWhatWasNotAcknowledged() {
		Recorder r = new Recorder();
		SignalOutbox outbox = new SignalOutbox(r);
		outbox.connected();
		for (long seq = 0; seq < 4; seq++) {
			outbox.offer(signal(seq));
		}
		r.outcomes.get(0).accept(Outcome.ACKNOWLEDGED);
		r.outcomes.get(2).accept(Outcome.ACKNOWLEDGED); // acknowledgements may come in any order
		outbox.disconnected();
		r.outcomes.get(1).accept(Outcome.LOST);
		r.outcomes.get(3).accept(Outcome.LOST);
		outbox.connected();
		assertEquals(List.of(1L, 3L), r.sent.subList(4, r.sent.size()));
	}

	@Test
	void dropsWhatTheRouterRefuses() {
		Recorder r = new Recorder();
		SignalOutbox outbox = new SignalOutbox(r);
		outbox.connected();
		outbox.offer(signal(0));
		r.settle(0, Outcome.REFUSED);
		assertEquals(0, outbox.pending());
		assertEquals(1, outbox.refused());
		outbox.disconnected();
		assertEquals(0, outbox.connected(), "a refused signal is not sent again");
	}

	@Test
	void survivesATransportThatAnswersAtOnce() {
		// jawampa fails a publication of a closed client before publish() returns
		List<Long> sent = new ArrayList<>();
		SignalOutbox outbox = new SignalOutbox((s, done) -> {
			sent.add(s.seq());
			done.accept(Outcome.LOST);
		});
		outbox.offer(signal(0));
		outbox.offer(signal(1));
		assertEquals(2, outbox.connected());
		assertEquals(2, outbox.connected());
		assertEquals(List.of(0L, 1L, 0L, 1L), sent);
		assertEquals(2, outbox.pending());
	}

	@Test
	void awaitingTheAcknowledgementsIsBounded() throws Exception {
		Recorder r = new Recorder();
		SignalOutbox outbox = new SignalOutbox(r);
		assertTrue(outbox.awaitEmpty(0));
		outbox.offer(signal(0));
		long start = System.nanoTime();
		assertFalse(outbox.awaitEmpty(200), "disconnected: nothing can be acknowledged");
		assertTrue(System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5));
		outbox.connected();
		Thread acknowledger = new Thread(() -> r.settle(0, Outcome.ACKNOWLEDGED));
		acknowledger.start();
		assertTrue(outbox.awaitEmpty(10_000));
		acknowledger.join();
	}

	/**
	 * A pipeline thread emits while a "jawampa" thread (one executor, like jawampa's) loses and restores the session
	 * and acknowledges at random: each session's wire carries increasing seqs and every signal is acknowledged.
	 */
	@Test
	void keepsTheOrderAndLosesNothingAcrossReconnections() throws Exception {
		int count = 2000;
		ExecutorService wamp = Executors.newSingleThreadExecutor();
		Random random = new Random(42);
		List<List<Long>> wire = new ArrayList<>(); // per session; touched on the wamp thread only
		List<Consumer<Outcome>> inFlight = new ArrayList<>();
		Set<Long> acknowledged = new TreeSet<>();
		boolean[] up = { false };
		SignalOutbox[] box = new SignalOutbox[1];
		box[0] = new SignalOutbox((s, done) -> wamp.execute(() -> {
			if (!up[0]) {
				done.accept(Outcome.LOST); // NOT_CONNECTED
				return;
			}
			wire.get(wire.size() - 1).add(s.seq());
			Consumer<Outcome> acknowledge = o -> {
				if (o == Outcome.ACKNOWLEDGED) {
					acknowledged.add(s.seq());
				}
				done.accept(o);
			};
			if (random.nextInt(3) == 0) {
				acknowledge.accept(Outcome.ACKNOWLEDGED);
			} else {
				inFlight.add(acknowledge); // answered later, or lost with the session
			}
		}));
		SignalOutbox outbox = box[0];
		Runnable connect = () -> {
			up[0] = true;
			wire.add(new ArrayList<>());
			outbox.connected();
		};
		Runnable disconnect = () -> {
			up[0] = false;
			outbox.disconnected(); // the status change comes first, then the session's requests fail
			inFlight.forEach(done -> done.accept(Outcome.LOST));
			inFlight.clear();
		};
		Runnable acknowledgeSome = () -> {
			inFlight.forEach(done -> done.accept(Outcome.ACKNOWLEDGED));
			inFlight.clear();
		};
		wamp.submit(connect).get();
		Thread pipeline = new Thread(() -> {
			for (long seq = 0; seq < count; seq++) {
				outbox.offer(signal(seq));
				if (seq % 50 == 0) {
					Thread.yield();
				}
			}
		});
		pipeline.start();
		while (pipeline.isAlive()) {
			// as jawampa: the reconnection is scheduled after the loss was handled
			wamp.submit(disconnect).get();
			wamp.submit(connect).get();
			wamp.submit(acknowledgeSome).get();
		}
		pipeline.join();
		wamp.submit(acknowledgeSome).get();
		wamp.submit(disconnect).get();
		wamp.submit(connect).get();
		wamp.submit(acknowledgeSome).get();
		assertTrue(outbox.awaitEmpty(10_000), () -> outbox.pending() + " signals never acknowledged");
		wamp.shutdown();
		assertTrue(wamp.awaitTermination(10, TimeUnit.SECONDS));

		assertEquals(count, acknowledged.size());
		assertTrue(wire.size() > 2, "the test reconnected");
		for (List<Long> session : wire) {
			for (int i = 1; i < session.size(); i++) {
				assertTrue(session.get(i - 1) < session.get(i), "out of order within a session: " + session);
			}
		}
	}
}
