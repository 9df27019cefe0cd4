/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.runtime;

/**
 * A match of a query that appeared (FOUND) or disappeared (LOST), at the simulation time of the state message
 * that caused it (thesis 9.2.2.1: {@code queryEvent atomicX() as findX found/lost}).
 */
public final class QueryEvent extends SessionEvent {

	/** Whether the match appeared or disappeared. */
	public enum Kind {
		FOUND, LOST
	}

	private final String query;
	private final Kind kind;

	public QueryEvent(String query, Kind kind, String subject, String target, double range, double t) {
		super(subject, target, range, t);
		this.query = query;
		this.kind = kind;
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
	public String toString() {
		return query + " " + kind + " " + getSubject() + " " + getTarget() + " " + getRange() + " @" + getT();
	}
}
