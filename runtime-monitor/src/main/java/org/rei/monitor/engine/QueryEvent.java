/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import org.rei.monitor.signals.Observation;

/**
 * A match of a query that appeared (FOUND) or disappeared (LOST), at the simulation time of the state message
 * that caused it (thesis 9.2.2.1: {@code queryEvent atomicX() as findX found/lost}). An event in the session,
 * declared in the transition rules with its timestamp in milliseconds of simulation time.
 */
public final class QueryEvent implements Observation {

	/** Whether the match appeared or disappeared. */
	public enum Kind {
		FOUND, LOST
	}

	private final String query;
	private final Kind kind;
	private final String subject;
	private final String target;
	private final double range;
	private final double t;
	private final long timestamp;

	public QueryEvent(String query, Kind kind, String subject, String target, double range, double t) {
		this.query = query;
		this.kind = kind;
		this.subject = subject;
		this.target = target;
		this.range = range;
		this.t = t;
		this.timestamp = Math.round(t * 1000);
	}

	public String getQuery() {
		return query;
	}

	public Kind getKind() {
		return kind;
	}

	public boolean isFound() {
		return kind == Kind.FOUND;
	}

	public boolean isLost() {
		return kind == Kind.LOST;
	}

	@Override
	public String getSubject() {
		return subject;
	}

	@Override
	public String getTarget() {
		return target;
	}

	@Override
	public double getRange() {
		return range;
	}

	@Override
	public double getT() {
		return t;
	}

	public long getTimestamp() {
		return timestamp;
	}

	@Override
	public String toString() {
		return query + " " + kind + " " + subject + " " + target + " " + range + " @" + t;
	}
}
