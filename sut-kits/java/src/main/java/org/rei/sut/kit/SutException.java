/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/** Why a SUT stopped, with the exit code {@link SutClient#runAndExit} uses. */
public final class SutException extends RuntimeException {

	private static final long serialVersionUID = 1L;

	private final int exitCode;

	public SutException(int exitCode, String message) {
		this(exitCode, message, null);
	}

	public SutException(int exitCode, String message, Throwable cause) {
		super(message, cause);
		this.exitCode = exitCode;
	}

	/** {@link SutClient#EXIT_CALLBACK} or {@link SutClient#EXIT_CONNECTION}. */
	public int exitCode() {
		return exitCode;
	}
}
