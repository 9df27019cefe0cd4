/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

import org.kie.api.KieBase;
import org.kie.api.KieServices;
import org.kie.api.builder.Message;
import org.kie.api.builder.Results;
import org.kie.api.conf.EventProcessingOption;
import org.kie.api.io.Resource;
import org.kie.api.io.ResourceType;
import org.kie.api.runtime.KieSession;
import org.kie.api.runtime.KieSessionConfiguration;
import org.kie.api.runtime.conf.ClockTypeOption;
import org.kie.api.time.SessionPseudoClock;
import org.kie.internal.utils.KieHelper;
import org.rei.vepl.compiler.CompiledRules;
import org.rei.vepl.compiler.DrlTarget;
import org.rei.vepl.compiler.VeplLoader;
import org.rei.vepl.runtime.MissionEvent;
import org.rei.vepl.runtime.QueryEvent;

/**
 * Compiles VEPL text and runs it on a STREAM session with a pseudo clock, the way the monitor does: events are
 * inserted at their time, then rules fire. Events are written {@code +q} (FOUND of q), {@code -q} (LOST of q) or
 * {@code !KIND} (mission event).
 */
public final class Cep implements AutoCloseable {

	static final Set<String> QUERIES = Set.of("a", "b", "c", "d", "robotFar", "robotClose", "robotInCollision",
			"laserSensesNothingClose", "laserSensesCloseness", "laserSensesCollision", "collisionWithObject");

	final CompiledRules rules;
	final KieSession session;
	final RecordingSink sink = new RecordingSink();
	private final SessionPseudoClock clock;

	Cep(String vepl) throws VeplLoader.VeplException {
		this(List.of(new VeplLoader.Source("test.vepl", vepl)));
	}

	Cep(List<VeplLoader.Source> sources) throws VeplLoader.VeplException {
		rules = VeplLoader.compile(sources, QUERIES, DrlTarget.MONITOR);
		session = build(rules);
		session.setGlobal("signals", sink);
		clock = session.getSessionClock();
	}

	// building a KieBase takes most of a test's time: identical rule sets share one
	private static final Map<String, KieBase> BASES = new ConcurrentHashMap<>();

	static KieSession build(CompiledRules rules) {
		KieServices ks = KieServices.Factory.get();
		KieSessionConfiguration conf = ks.newKieSessionConfiguration();
		conf.setOption(ClockTypeOption.PSEUDO);
		String key = rules.files().toString();
		return BASES.computeIfAbsent(key, k -> base(rules)).newKieSession(conf, null);
	}

	private static KieBase base(CompiledRules rules) {
		KieServices ks = KieServices.Factory.get();
		KieHelper helper = new KieHelper();
		for (CompiledRules.DrlFile f : rules.files()) {
			Resource r = ks.getResources().newByteArrayResource(f.text().getBytes(StandardCharsets.UTF_8));
			r.setSourcePath("src/main/resources/rei/" + f.name());
			helper.addResource(r, ResourceType.DRL);
		}
		Results results = helper.verify();
		if (results.hasMessages(Message.Level.ERROR)) {
			throw new IllegalStateException(results.getMessages(Message.Level.ERROR) + "\n" + rules.files());
		}
		return helper.build(EventProcessingOption.STREAM);
	}

	/** Advances the clock to {@code ms} and inserts the events (all at that time), then fires. */
	Cep at(long ms, String... events) {
		long delta = ms - clock.getCurrentTime();
		if (delta > 0) {
			clock.advanceTime(delta, TimeUnit.MILLISECONDS);
		}
		for (String e : events) {
			String subject = "r";
			int slash = e.indexOf('/');
			if (slash > 0) {
				subject = e.substring(slash + 1);
				e = e.substring(0, slash);
			}
			switch (e.charAt(0)) {
			case '+' -> session.insert(queryEvent(e.substring(1), QueryEvent.Kind.FOUND, subject, ms));
			case '-' -> session.insert(queryEvent(e.substring(1), QueryEvent.Kind.LOST, subject, ms));
			case '!' -> session.insert(new MissionEvent(e.substring(1), -1, subject, 0, ms / 1000.0)); // no task
			default -> throw new IllegalArgumentException(e);
			}
		}
		session.fireAllRules();
		return this;
	}

	/** A query event whose target is the query's name, so a signal's target tells which event it reports. */
	static QueryEvent queryEvent(String query, QueryEvent.Kind kind, String subject, long ms) {
		return new QueryEvent(query, kind, subject, query, 0, ms / 1000.0);
	}

	List<String> signals() {
		return new ArrayList<>(sink.emitted);
	}

	@Override
	public void close() {
		session.dispose();
	}
}
