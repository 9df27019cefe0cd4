/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.server;

/** A request the engine cannot carry out as written (a missing field, an unknown command or op): answered ok:false. */
final class RequestException extends Exception {

	private static final long serialVersionUID = 1L;

	RequestException(String message) {
		super(message);
	}
}
