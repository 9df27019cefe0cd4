/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.signals;

import java.util.LinkedHashMap;
import java.util.Map;

/** A message of {@code rei.run.<id>.signal}: {@code seq} counts from 0 without gaps. */
public record Signal(long seq, double t, String signal, String subject, String object, double distance) {

	/** The payload on the wire and in {@code --signals-out}, keys in the documented order (docs/protocol.md). */
	public Map<String, Object> payload() {
		Map<String, Object> payload = new LinkedHashMap<>();
		payload.put("seq", seq);
		payload.put("t", t);
		payload.put("signal", signal);
		payload.put("subject", subject);
		payload.put("object", object);
		payload.put("distance", distance);
		return payload;
	}

	/** One line per signal, the format of {@code --replay} output and of test expectations. */
	public String line() {
		return String.format(java.util.Locale.ROOT, "%d %.3f %s %s %s %.4f", seq, t, signal, subject, object,
				distance);
	}
}
