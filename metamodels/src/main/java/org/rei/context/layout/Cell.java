/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.layout;

/** Integer grid cell of a floor: column {@code x} from the left, row {@code y} from the bottom. */
public record Cell(int x, int y) {

	@Override
	public String toString() {
		return "(" + x + ", " + y + ")";
	}
}
