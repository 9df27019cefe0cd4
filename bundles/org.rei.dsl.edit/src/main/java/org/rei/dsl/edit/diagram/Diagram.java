/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.diagram;

import java.util.List;

/**
 * A snapshot of a test case as the room editor draws it: plain values in metres, seconds and degrees, with every
 * element named as in the text so that an edit or a validation issue can point at it. Coordinates come from the
 * floor layout the generators use (x to the right, y up, origin at the bottom-left corner of the room); they are
 * null for a floor the layout could not place.
 */
public record Diagram(String testCase, Room room, List<Item> objects, Item robot, List<Mover> movers,
		Mission mission, Monitor monitor, List<CrowdAreas> crowds, List<GroupRoute> groups) {

	/**
	 * @param form "grid" ({@code size C x R}), "map", "occupancy" (an occupancy map) or "graph" (floors and walls
	 *             written out)
	 * @param columns cells along x of the laid-out floors
	 * @param map the occupancy map of an "occupancy" room (drawn under its floors), else {@code null}
	 */
	public record Room(String name, String form, double floorSize, int columns, int rows, List<FloorCell> floors,
			List<WallSide> walls, OccupancyMap map) {
	}

	/**
	 * An occupancy room's map: its files (absolute paths) and where its image lies in the room: the image's
	 * bottom-left corner at the origin, {@code width x height} cells of {@code resolution} metres.
	 */
	public record OccupancyMap(String yaml, String image, double resolution, double originX, double originY,
			int width, int height, boolean unknownFree) {
	}

	/** @param written whether the floor is a statement of the text (not derived from a grid or a map) */
	public record FloorCell(String name, String type, Integer x, Integer y, Double centreX, Double centreY,
			boolean written) {
	}

	/** A wall on one side of the first floor that names it, as an axis-aligned box. */
	public record WallSide(String name, String type, String floor, String side, double x, double y, double sizeX,
			double sizeY, boolean written) {
	}

	/**
	 * What a catalogue type says about an element's outline: {@code box}, {@code cylinder} or {@code polygon}, sizes
	 * in metres (a polygon's its bounding box's); a robot type read from a URDF or xacro description also names it
	 * ({@code description}, else null), whose outline only REI's Python reader computes (the room editor's server
	 * adds it). A polygon type's {@code outline} is its polygon about the item's place, as world.json's footprint
	 * (left out of the JSON for every other type).
	 */
	public record Footprint(String type, String shape, double sizeX, double sizeY, double height, String colour,
			Description description,
			@com.fasterxml.jackson.annotation.JsonInclude(com.fasterxml.jackson.annotation.JsonInclude.Include.NON_NULL)
			Outline outline) {

		public Footprint(String type, String shape, double sizeX, double sizeY, double height, String colour) {
			this(type, shape, sizeX, sizeY, height, colour, null, null);
		}

		public Footprint(String type, String shape, double sizeX, double sizeY, double height, String colour,
				Description description) {
			this(type, shape, sizeX, sizeY, height, colour, description, null);
		}
	}

	/** A polygon outline, {@code type} "polygon", its {@code [x, y]} points counter-clockwise. */
	public record Outline(String type, double[][] points) {
	}

	/**
	 * A robot type's description: its file's absolute path (resolved against its catalogue, as the generator does),
	 * its xacro arguments in the catalogue's order and its lidar's link.
	 */
	public record Description(String file, java.util.Map<String, String> args, String lidar) {
	}

	/** Furniture or the robot on a floor; {@code x, y} is the floor's centre. */
	public record Item(String name, String kind, String floor, double yaw, Double x, Double y, Footprint footprint) {
	}

	/**
	 * A human or a moving object and its control points; or a person who walks a route and sees the robot: no
	 * control points, its {@code route} instead (null for everything on rails).
	 *
	 * @param loop whether the trajectory, or the route, starts over after its last point or stop
	 */
	public record Mover(String name, String kind, Footprint footprint, List<Waypoint> points, boolean loop,
			Route route) {
	}

	public record Waypoint(String floor, double seconds, Double x, Double y) {
	}

	/**
	 * The way of a person who sees the robot: its stops in order (it stands on the first at the start of the run),
	 * walking speed in m/s, the time it sets off, and its behaviour towards the robot as the text writes it
	 * ({@code avoids}, {@code ignores}, {@code curious}, {@code scared}, {@code blocks}).
	 */
	public record Route(List<Stop> stops, double speed, double start, String behaviour) {
	}

	/** A stop of a route: a floor, the seconds the person waits there, and the floor's centre. */
	public record Stop(String floor, double waitSeconds, Double x, Double y) {
	}

	/**
	 * A crowd as its line writes it: how many people, their type, the floors they stand spread over ({@code from})
	 * and those they walk to ({@code to}), in the text's order, and the people a second who set off (null: all at
	 * once). Its people are placed by the generator, so the diagram draws its areas, not them.
	 */
	public record CrowdAreas(String name, int count, Footprint footprint, List<Area> from, List<Area> to,
			Double rate, double speed, boolean loop, String behaviour) {
	}

	/** A floor of a crowd's area and its centre. */
	public record Area(String floor, Double x, Double y) {
	}

	/** A group: {@code count} people who walk one route together (its leader's). */
	public record GroupRoute(String name, int count, Footprint footprint, Route route, boolean loop) {
	}

	/** @param timeout the goal's own timeout, null when the mission's task timeout applies */
	public record Goal(int index, String floor, Double timeout, Double x, Double y) {
	}

	public record Mission(String name, double tolerance, double taskTimeout, List<Goal> goals) {
	}

	public record Monitor(double close, double collision, int maxHumanCollisions) {
	}
}
