/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.drools.base.definitions.rule.impl.QueryImpl;
import org.drools.base.rule.Declaration;
import org.eclipse.emf.ecore.EObject;
import org.kie.api.definition.KiePackage;
import org.kie.api.definition.rule.Query;
import org.kie.api.event.rule.AfterMatchFiredEvent;
import org.kie.api.event.rule.AgendaEventListener;
import org.kie.api.event.rule.DefaultAgendaEventListener;
import org.kie.api.runtime.KieSession;
import org.kie.api.runtime.rule.FactHandle;
import org.kie.api.runtime.rule.LiveQuery;
import org.kie.api.runtime.rule.Row;
import org.kie.api.runtime.rule.Variable;
import org.kie.api.runtime.rule.ViewChangedEventListener;
import org.kie.api.time.SessionPseudoClock;
import org.rei.vepl.runtime.MissionEvent;
import org.rei.vepl.runtime.QueryEvent;
import org.rei.vepl.runtime.SignalSink;

/**
 * The incremental part of the monitor: keeps the facts (thresholds, robot, one proximity per nearby obstacle,
 * laser) in the Drools session, turns the appearing and disappearing matches of every query into
 * {@link QueryEvent}s at the simulation time of the step (live queries), and lets the transition rules turn
 * those into signals. The pseudo clock follows simulation time.
 *
 * <p>Every query of the loaded files is watched. A query declares any of {@code String subject} (default: the
 * robot), {@code String target} (default: none, the empty string) and {@code double range} (default: 0, as for the
 * mission's events): they
 * become the event's subject, target and range, and so a signal's subject, object and distance. The runtime model
 * is in the session too ({@link ModelFacts}), so a query may match the EMF model's objects as they are.
 */
public final class MonitorEngine implements AutoCloseable {

	private final KieSession session;
	private final SessionPseudoClock clock;
	private final RobotFact robot;
	private final FactHandle robotHandle;
	private LaserReading laser;
	private FactHandle laserHandle;
	private final Map<String, Slot> proximities = new HashMap<>();
	private final List<LiveQuery> liveQueries = new ArrayList<>();
	private final List<QueryEvent> pending = new ArrayList<>();
	private final List<QueryEvent> queryEventLog;
	private final ModelFacts model;
	private double now;
	private long step;

	private static final class Slot {
		final Proximity fact;
		FactHandle handle;
		long seen;

		Slot(Proximity fact) {
			this.fact = fact;
		}
	}

	/**
	 * @param model         the runtime model the queries may match (its containment tree), or null
	 * @param queryEventLog receives every query event in order (tests, debugging), or null
	 */
	public MonitorEngine(KieSession session, Thresholds thresholds, String robotName, SignalSink signals,
			EObject model, List<QueryEvent> queryEventLog) {
		this.session = session;
		this.clock = session.getSessionClock();
		this.queryEventLog = queryEventLog;
		session.setGlobal("signals", signals);
		session.insert(thresholds);
		robot = new RobotFact(robotName);
		robotHandle = session.insert(robot);
		// The laser starts like the geometry, sensing nothing close: a first reading in CLOSE or COLLISION is a
		// transition (and the signals of both state machines then start from the same FAR).
		laser = new LaserReading(robotName, "laser", Double.POSITIVE_INFINITY);
		laserHandle = session.insert(laser);
		this.model = model == null ? null : ModelFacts.attach(session, model);
		for (KiePackage pkg : session.getKieBase().getKiePackages()) {
			for (Query q : pkg.getQueries()) {
				watch(q);
			}
		}
		session.fireAllRules();
		pending.clear(); // matches present before the first message are the initial state, not events
	}

	private void watch(Query q) {
		String query = q.getName();
		Declaration[] parameters = q instanceof QueryImpl impl ? impl.getParameters() : new Declaration[0];
		Set<String> declared = new HashSet<>();
		for (Declaration d : parameters) {
			declared.add(d.getIdentifier());
		}
		String robotName = robot.getName();
		ViewChangedEventListener listener = new ViewChangedEventListener() {
			@Override
			public void rowInserted(Row row) {
				pending.add(event(query, QueryEvent.Kind.FOUND, row, declared, robotName));
			}

			@Override
			public void rowDeleted(Row row) {
				pending.add(event(query, QueryEvent.Kind.LOST, row, declared, robotName));
			}

			@Override
			public void rowUpdated(Row row) {
				// the same match with new values (a distance changed): not an event
			}
		};
		Object[] arguments = new Object[parameters.length];
		Arrays.fill(arguments, Variable.v);
		liveQueries.add(session.openLiveQuery(query, arguments, listener));
	}

	private QueryEvent event(String query, QueryEvent.Kind kind, Row row, Set<String> declared, String robotName) {
		String subject = declared.contains("subject") ? String.valueOf(row.get("subject")) : robotName;
		String target = declared.contains("target") ? String.valueOf(row.get("target")) : "";
		Object range = declared.contains("range") ? row.get("range") : null;
		return new QueryEvent(query, kind, subject, target, range instanceof Number n ? n.doubleValue() : 0.0, now);
	}

	/** Starts a state step at simulation time {@code t} (seconds); the pseudo clock never runs backwards. */
	public void beginStep(double t) {
		now = t;
		step++;
		advanceClock(t);
	}

	private void advanceClock(double t) {
		long target = Math.round(t * 1000);
		long delta = target - clock.getCurrentTime();
		if (delta > 0) {
			clock.advanceTime(delta, TimeUnit.MILLISECONDS);
		}
	}

	/** Reports the footprint distance to one nearby obstacle in this step. */
	public void proximity(String object, String category, double distance, boolean contact) {
		Slot slot = proximities.get(object);
		if (slot == null) {
			slot = new Slot(new Proximity(robot.getName(), object, category, distance, contact));
			slot.handle = session.insert(slot.fact);
			proximities.put(object, slot);
		} else if (slot.fact.set(distance, contact)) {
			session.update(slot.handle, slot.fact);
		}
		slot.seen = step;
	}

	/** Reports the laser's distance (see {@link LaserReading}); NaN when this step has no laser data. */
	public void laser(double distance) {
		if (Double.isNaN(distance)) {
			return;
		}
		if (laser.set(distance)) {
			session.update(laserHandle, laser);
		}
	}

	/** Ends the step: obstacles not reported are no longer near; queries and transition rules run. */
	public void endStep(String nearestObject, double nearestDistance) {
		for (Iterator<Slot> it = proximities.values().iterator(); it.hasNext();) {
			Slot slot = it.next();
			if (slot.seen != step) {
				session.delete(slot.handle);
				it.remove();
			}
		}
		if (robot.set(nearestObject, nearestDistance)) {
			session.update(robotHandle, robot);
		}
		fire();
	}

	/** A mission event at simulation time {@code t}. */
	public void mission(MissionEvent event) {
		now = Math.max(now, event.getT());
		advanceClock(event.getT());
		session.insert(event);
		fire();
	}

	// live-query callbacks arrive inside fireAllRules; the events they produce are inserted afterwards
	private void fire() {
		if (model != null) {
			model.flush();
		}
		session.fireAllRules();
		while (!pending.isEmpty()) {
			List<QueryEvent> batch = new ArrayList<>(pending);
			pending.clear();
			for (QueryEvent e : batch) {
				if (queryEventLog != null) {
					queryEventLog.add(e);
				}
				session.insert(e);
			}
			session.fireAllRules();
		}
	}

	/** Names of the rules that fired, for tests that assert them (STYLE: assert fired rules by name). */
	public void addAgendaListener(AgendaEventListener listener) {
		session.addEventListener(listener);
	}

	/** A listener that records the name of every fired rule. */
	public static AgendaEventListener firedRuleRecorder(List<String> into) {
		return new DefaultAgendaEventListener() {
			@Override
			public void afterMatchFired(AfterMatchFiredEvent event) {
				into.add(event.getMatch().getRule().getName());
			}
		};
	}

	public long factCount() {
		return session.getFactCount();
	}

	public int nearbyCount() {
		return proximities.size();
	}

	@Override
	public void close() {
		for (LiveQuery q : liveQueries) {
			q.close();
		}
		session.dispose();
	}
}
