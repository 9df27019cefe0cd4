/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

/** Cells {@code [col, col + cols) x [row, row + rows)} of a map's grid (row 0 at the bottom). */
public record CellRect(int col, int row, int cols, int rows) {
}
