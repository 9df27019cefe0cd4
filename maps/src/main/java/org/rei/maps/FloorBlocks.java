/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

/**
 * The floor blocks of a map: {@code columns x rows} blocks of {@code floorSize} metres counted from the map's origin,
 * each with the number of obstacle cells it overlaps; block {@code (x, y)} is the floor {@code F_x_y} when that
 * number is 0.
 */
public final class FloorBlocks {

	private final double floorSize;
	private final int columns;
	private final int rows;
	private final int[] obstacles;
	private final int[] columnCells;
	private final int[] rowCells;
	private final int freeCount;

	FloorBlocks(double floorSize, int columns, int rows, int[] obstacles, int[] columnCells, int[] rowCells) {
		this.floorSize = floorSize;
		this.columns = columns;
		this.rows = rows;
		this.obstacles = obstacles;
		this.columnCells = columnCells;
		this.rowCells = rowCells;
		int free = 0;
		for (int count : obstacles) {
			free += count == 0 ? 1 : 0;
		}
		this.freeCount = free;
	}

	public double floorSize() {
		return floorSize;
	}

	/** Blocks along x (only blocks wholly inside the map). */
	public int columns() {
		return columns;
	}

	/** Blocks along y. */
	public int rows() {
		return rows;
	}

	/** Whether block {@code (x, y)} exists. */
	public boolean contains(int x, int y) {
		return x >= 0 && y >= 0 && x < columns && y < rows;
	}

	/** Whether block {@code (x, y)} exists and every cell it overlaps is free. */
	public boolean isFree(int x, int y) {
		return contains(x, y) && obstacles[y * columns + x] == 0;
	}

	/** Obstacle cells block {@code (x, y)} overlaps. */
	public int obstacleCells(int x, int y) {
		return obstacles[y * columns + x];
	}

	/** Cells block {@code (x, y)} overlaps. */
	public int cells(int x, int y) {
		return columnCells[x] * rowCells[y];
	}

	/** The number of free blocks. */
	public int freeCount() {
		return freeCount;
	}
}
