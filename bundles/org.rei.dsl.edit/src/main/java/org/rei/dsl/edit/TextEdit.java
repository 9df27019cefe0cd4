/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

/** Replace {@code length} characters at {@code offset} of the previous text by {@code replacement}. */
public record TextEdit(int offset, int length, String replacement) {

	public int end() {
		return offset + length;
	}
}
