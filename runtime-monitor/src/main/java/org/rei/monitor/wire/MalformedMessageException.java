/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wire;

/** A message that does not follow the wire protocol; {@code kind} groups problems for counting and logging. */
public final class MalformedMessageException extends Exception {

	private static final long serialVersionUID = 1L;

	private final String kind;

	public MalformedMessageException(String kind, String detail) {
		super(kind + ": " + detail);
		this.kind = kind;
	}

	public MalformedMessageException(String kind, String detail, Throwable cause) {
		super(kind + ": " + detail, cause);
		this.kind = kind;
	}

	public String kind() {
		return kind;
	}
}
