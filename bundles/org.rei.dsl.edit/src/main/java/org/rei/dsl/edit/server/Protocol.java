/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.server;

import java.util.List;

/**
 * The engine's words in the room editor's protocol (docs/room-editor.md), public so that the contract test reads
 * them from the built jar and compares them with contract/vocabulary.json, the Python server's and the page's.
 */
public final class Protocol {

	/** The requests the engine answers. */
	public static final List<String> COMMANDS = List.of("open", "state", "apply", "undo", "redo", "reset");

	/**
	 * The operations' {@code op} names: each is its {@link org.rei.dsl.edit.EditOperation} record's simple name with
	 * a lower-case first letter, and its fields are that record's components.
	 */
	public static final List<String> OPERATIONS = List.of("moveObject", "rotateObject", "addObject", "deleteObject",
			"addHuman", "addDynamic", "addFloor", "removeFloor", "addWall", "removeWall", "setTrajectory", "setRoute",
			"addCrowd", "setCrowd", "addGoal", "removeGoal", "moveGoal");

	/**
	 * The {@code kind} of an {@code ok: false} answer: {@code refused}, the request's fault (an edit the text cannot
	 * express, a missing field, an unknown command); {@code internal}, the engine's own failure (an exception in
	 * it, such as its jar replaced under it), which says nothing about the request.
	 */
	public static final String REFUSED = "refused";
	public static final String INTERNAL = "internal";
	public static final List<String> ERROR_KINDS = List.of(REFUSED, INTERNAL);

	/** Sides of a floor and neighbour keys: the grammar's keywords. */
	public static final List<String> SIDES = List.of("top", "right", "bottom", "left");

	private Protocol() {
	}
}
