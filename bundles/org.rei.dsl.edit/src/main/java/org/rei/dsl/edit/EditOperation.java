/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.rei.context.Direction;

/**
 * One edit of a room as a diagram makes it. Elements are named as in the text; goals are counted from 0 in the
 * mission's order. {@link RoomDocument#apply} applies a batch of them as one change.
 */
public sealed interface EditOperation {

	/** Puts a piece of furniture or the robot on another floor. */
	record MoveObject(String name, String floor) implements EditOperation {
	}

	/** Turns a piece of furniture or the robot: {@code yaw} in degrees, counter-clockwise from +x (0 omits it). */
	record RotateObject(String name, double yawDegrees) implements EditOperation {
	}

	/** Places new furniture: {@code object NAME : TYPE on FLOOR}; the type comes from the catalogues in scope. */
	record AddObject(String name, String type, String floor) implements EditOperation {
	}

	/**
	 * Adds a human that walks through the control points: {@code human NAME (: TYPE)? trajectory [...] loop};
	 * {@code type} null for the default catalogue's Human. {@code loop} false is written as nothing (the grammar's
	 * default, which {@code once} only spells out).
	 */
	record AddHuman(String name, String type, List<Waypoint> points, boolean loop) implements EditOperation {
		public AddHuman {
			points = List.copyOf(points);
		}
	}

	/**
	 * Adds a moving object that follows the control points: {@code dynamic NAME : TYPE trajectory [...] loop}; the
	 * type is required (the grammar has no default for it). {@code loop} false is written as nothing, as for humans.
	 */
	record AddDynamic(String name, String type, List<Waypoint> points, boolean loop) implements EditOperation {
		public AddDynamic {
			Objects.requireNonNull(type, "type");
			points = List.copyOf(points);
		}
	}

	/** Removes furniture, a moving object or a human (not the robot: a room has exactly one). */
	record DeleteObject(String name) implements EditOperation {
	}

	/** Declares a floor of an explicit floor graph with the neighbours it names ({@code floor C left B}). */
	record AddFloor(String name, Map<Direction, String> neighbours) implements EditOperation {
		public AddFloor {
			neighbours = Map.copyOf(neighbours);
		}
	}

	/** Removes a floor of an explicit floor graph and every neighbour reference to it. */
	record RemoveFloor(String name) implements EditOperation {
	}

	/** Declares a wall and puts it on one side of a floor of an explicit floor graph. */
	record AddWall(String name, String floor, Direction side) implements EditOperation {
	}

	/** Removes a wall of an explicit floor graph and every reference to it. */
	record RemoveWall(String name) implements EditOperation {
	}

	/** Replaces the control points of a human's (or a moving object's) trajectory; {@code loop} or once. */
	record SetTrajectory(String name, List<Waypoint> points, boolean loop) implements EditOperation {
		public SetTrajectory {
			points = List.copyOf(points);
		}
	}

	/**
	 * Replaces the route of a person who sees the robot: its stops in order, walking speed (m/s), start (s), loop or
	 * once, and behaviour as the text writes it ({@code avoids}, {@code ignores}, {@code curious}, {@code scared},
	 * {@code blocks}). What differs from the route as written changes in place; the rest of its line stays as
	 * written.
	 */
	record SetRoute(String name, List<Stop> stops, double speed, double start, boolean loop, String behaviour)
			implements EditOperation {
		public SetRoute {
			stops = List.copyOf(stops);
			Objects.requireNonNull(behaviour, "behaviour");
		}
	}

	/**
	 * Adds a crowd ({@code crowd NAME COUNT (: TYPE)? from [...] to [...] rate RATE}): {@code count} people who stand
	 * spread over the {@code from} floors and walk to the {@code to} floors; {@code type} null for the default
	 * Human, {@code rate} (people a second) null when all set off at once.
	 */
	record AddCrowd(String name, String type, int count, List<String> from, List<String> to, Double rate)
			implements EditOperation {
		public AddCrowd {
			from = List.copyOf(from);
			to = List.copyOf(to);
		}
	}

	/**
	 * Changes a crowd's size, areas and rate in place: a changed floor or number replaces just its token, the rest of
	 * its line (speed, start, loop, behaviour, layout over several lines) stays as written; {@code rate} null
	 * removes it (all set off at once).
	 */
	record SetCrowd(String name, int count, List<String> from, List<String> to, Double rate) implements EditOperation {
		public SetCrowd {
			from = List.copyOf(from);
			to = List.copyOf(to);
		}
	}

	/** A stop of a route: the centre of a floor, and the seconds the person waits there on arrival. */
	record Stop(String floor, double waitSeconds) {
		public Stop {
			Objects.requireNonNull(floor, "floor");
		}
	}

	/** A control point: the centre of a floor at a time in seconds. */
	record Waypoint(String floor, double seconds) {
		public Waypoint {
			Objects.requireNonNull(floor, "floor");
		}
	}

	/** Inserts a goal at {@code index} (the goal count appends); {@code timeoutSeconds} null for the mission's. */
	record AddGoal(String floor, int index, Double timeoutSeconds) implements EditOperation {
		public AddGoal(String floor, int index) {
			this(floor, index, null);
		}
	}

	record RemoveGoal(int index) implements EditOperation {
	}

	/** Moves the goal at {@code from} so that it ends up at {@code to}. */
	record MoveGoal(int from, int to) implements EditOperation {
	}
}
