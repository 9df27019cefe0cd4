/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.model;

import java.util.HashMap;
import java.util.Map;

import org.rei.context.Floor;

/**
 * The inverse of the generator's floor-to-coordinate mapping (docs/artifacts.md): floor cell {@code (i, j)} covers
 * {@code [i, i+1) x [j, j+1)} times the floor size, so the floor under a point is one division away.
 */
public final class FloorGrid {

	private final double floorSize;
	private final Map<Long, Floor> cells = new HashMap<>();

	public FloorGrid(double floorSize) {
		if (!(floorSize > 0)) {
			throw new IllegalArgumentException("floor size must be positive, got " + floorSize);
		}
		this.floorSize = floorSize;
	}

	public void put(int i, int j, Floor floor) {
		cells.put(key(i, j), floor);
	}

	/** The floor under {@code (x, y)}, or null outside the room or over a hole. */
	public Floor floorAt(double x, double y) {
		return cells.get(key((int) Math.floor(x / floorSize), (int) Math.floor(y / floorSize)));
	}

	private static long key(int i, int j) {
		return ((long) i << 32) ^ (j & 0xffffffffL);
	}
}
