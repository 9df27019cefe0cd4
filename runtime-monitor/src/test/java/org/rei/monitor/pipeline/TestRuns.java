/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rei.monitor.config.CaseReader;
import org.rei.monitor.engine.DrlSources;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.signals.SignalPublisher;
import org.rei.vepl.runtime.QueryEvent;

/** A monitor on the test room (src/test/resources/cases/room) with the packaged rules, recording its output. */
public final class TestRuns implements AutoCloseable {

	public final List<Signal> signals = new ArrayList<>();
	public final List<QueryEvent> queryEvents = new ArrayList<>();
	public final List<String> log = new ArrayList<>();
	public final List<String> firedRules = new ArrayList<>();
	public final Monitor monitor;

	public TestRuns() {
		this(packagedRules());
	}

	/** With these rule files (queries and rules) instead of the packaged ones. */
	public TestRuns(List<DrlSources.Source> rules) {
		this(room(), rules);
	}

	/** On another case (the test room changed), with the packaged rules. */
	public TestRuns(CaseReader.Case c) {
		this(c, packagedRules());
	}

	private TestRuns(CaseReader.Case c, List<DrlSources.Source> rules) {
		SignalPublisher publisher = new SignalPublisher();
		publisher.addListener(signals::add);
		monitor = new Monitor("test", c.world(), c.monitor(), rules, publisher, log::add, queryEvents);
		monitor.engine().addAgendaListener(org.rei.monitor.engine.MonitorEngine.firedRuleRecorder(firedRules));
	}

	private static List<DrlSources.Source> packagedRules() {
		List<DrlSources.Source> rules = new ArrayList<>(DrlSources.packaged(DrlSources.QUERIES));
		rules.addAll(DrlSources.packaged(DrlSources.RULES));
		return rules;
	}

	public static Path roomFolder() {
		try {
			return Path.of(TestRuns.class.getResource("/cases/room/world.json").toURI()).getParent();
		} catch (URISyntaxException e) {
			throw new IllegalStateException(e);
		}
	}

	public static CaseReader.Case room() {
		try {
			return CaseReader.readFolder(roomFolder());
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}

	/** The signals whose name starts with {@code prefix}, as names. */
	public List<String> names(String prefix) {
		return signals.stream().map(Signal::signal).filter(s -> s.startsWith(prefix)).toList();
	}

	public List<Signal> of(String prefix) {
		return signals.stream().filter(s -> s.signal().startsWith(prefix)).toList();
	}

	@Override
	public void close() {
		monitor.close();
	}
}
