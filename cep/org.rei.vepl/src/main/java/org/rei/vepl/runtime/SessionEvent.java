/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.runtime;

/**
 * What query and mission events share: the observation a signal reports and the {@code timestamp} (milliseconds of
 * simulation time) the generated rules declare as the event's time, rounded as the monitor rounds its pseudo clock.
 * Equality is identity: two events with the same values are still two events.
 */
public abstract class SessionEvent implements Observation {

	private final String subject;
	private final String target;
	private final double range;
	private final double t;
	private final long timestamp;

	/** Only the events of this package: the generated rules know no others. */
	SessionEvent(String subject, String target, double range, double t) {
		this.subject = subject;
		this.target = target;
		this.range = range;
		this.t = t;
		this.timestamp = Math.round(t * 1000);
	}

	@Override
	public final String getSubject() {
		return subject;
	}

	@Override
	public final String getTarget() {
		return target;
	}

	@Override
	public final double getRange() {
		return range;
	}

	@Override
	public final double getT() {
		return t;
	}

	public final long getTimestamp() {
		return timestamp;
	}
}
