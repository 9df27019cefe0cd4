/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.signals;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

import org.rei.vepl.runtime.SignalSink;

/**
 * Numbers signals gap-free from 0 and hands them to the listeners (WAMP publisher, printer, tests) in order.
 * Single-threaded by design: the pipeline calls it from its one thread.
 */
public final class SignalPublisher implements SignalSink {

	private final List<Consumer<Signal>> listeners = new CopyOnWriteArrayList<>();
	private long seq;

	public void addListener(Consumer<Signal> listener) {
		listeners.add(listener);
	}

	@Override
	public void emit(String signal, double t, String subject, String object, double distance) {
		Signal s = new Signal(seq++, t, signal, subject, object == null ? "" : object, distance);
		for (Consumer<Signal> l : listeners) {
			l.accept(s);
		}
	}

	/** How many signals were emitted so far. */
	public long count() {
		return seq;
	}
}
