/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.cli;

import java.nio.file.Path;

/** A problem found in a test-case file, positioned for a person (1-based line and column). */
public record Diagnostic(Path file, int line, int column, Severity severity, String message, String code) {

	public enum Severity {
		ERROR, WARNING;

		@Override
		public String toString() {
			return name().toLowerCase(java.util.Locale.ROOT);
		}
	}

	public boolean isError() {
		return severity == Severity.ERROR;
	}

	/** The compiler convention editors and CI logs understand: {@code file:line:column: error: message [code]}. */
	@Override
	public String toString() {
		return file + ":" + line + ":" + column + ": " + severity + ": " + message + (code == null ? "" : " [" + code + "]");
	}
}
