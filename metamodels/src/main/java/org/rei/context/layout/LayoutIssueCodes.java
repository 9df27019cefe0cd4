/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.layout;

/** Codes of {@link LayoutProblem}s; validators and tests key on these, never on message text. */
public final class LayoutIssueCodes {

	private static final String PREFIX = "org.rei.layout.";

	/** Two floors land on the same cell. */
	public static final String OVERLAP = PREFIX + "overlap";

	/** A floor is reached at two different cells: its neighbour references form an inconsistent loop. */
	public static final String INCONSISTENT_LOOP = PREFIX + "inconsistentLoop";

	/** A floor is not connected to the start floor through neighbour references. */
	public static final String DISCONNECTED = PREFIX + "disconnected";

	/** A wall is named by floors whose sides lie in different places. */
	public static final String WALL_CONFLICT = PREFIX + "wallConflict";

	/** A wall no floor names as a neighbour, so it has no place. */
	public static final String ORPHAN_WALL = PREFIX + "orphanWall";

	private LayoutIssueCodes() {
	}
}
