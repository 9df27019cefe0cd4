/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.people;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.rei.catalogue.ObjectType;
import org.rei.context.BuildingBlock;
import org.rei.context.Crowd;
import org.rei.context.Direction;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.PhysicalObject;
import org.rei.context.layout.Cell;
import org.rei.context.layout.FloorLayout;

/**
 * Where the people of crowds and groups stand and where a crowd's people walk to (docs/language.md, "Crowds and
 * groups"); the validator counts what it finds, the generator places the people on it, so both agree.
 * <p>
 * An <b>area</b> (a set of floors) holds the points of a square lattice of spacing {@code 2 * radius + 0.1} m: the
 * first point {@code radius + 0.05} m in from the bottom-left corner of the area's bounding box, the points in rows
 * from the bottom, each row from the left. A point is kept when its disc of {@code radius + 0.05} m lies on the
 * area's floors and crosses no wall between two of them, so people of that radius stand 0.1 m apart and 0.05 m in
 * from the area's edge. A crowd's {@link #from} and {@link #to} areas are its floors; a group's followers stand on
 * the lattice of the leader's floor and of the free floors beside it, nearest the leader first, at least a spacing
 * from it ({@link #beside}).
 * <p>
 * A floor is free of everything that stands on it at the start of the run: furniture, the robot, the start of a
 * moving object or person (a group's leader's included), a crowd's from floors, a crowd's to floors (so a group
 * never stands where a crowd walks to) and the floors of an earlier group's followers (groups are placed in the
 * order of the text).
 */
public final class PeoplePlacement {

	/** Between two people's discs, in metres. */
	public static final double GAP = 0.1;
	/** Between a person's disc and the edge of its area, in metres. */
	public static final double CLEARANCE = 0.05;
	/** Half the x size of the default catalogue's Human, for a model without it. */
	public static final double DEFAULT_RADIUS = 0.25;

	private static final double EPS = 1e-9;

	/** A place of one person: the floor that holds it and the point in the world frame. */
	public record Spot(Floor floor, double x, double y) {
	}

	private final FloorLayout layout;
	private final ObjectType defaultHuman;
	private final Map<Floor, PhysicalObject> starts = new LinkedHashMap<>();
	private final Set<Floor> targets = new HashSet<>();
	private final Map<Group, List<Spot>> beside = new IdentityHashMap<>();

	private PeoplePlacement(Environment environment, FloorLayout layout, ObjectType defaultHuman) {
		this.layout = layout;
		this.defaultHuman = defaultHuman;
		starts.putAll(starts(environment));
		for (PhysicalObject object : environment.getOwnedObjects()) {
			if (object instanceof Crowd crowd) {
				targets.addAll(crowd.getTo());
			}
		}
		Set<Floor> followed = new HashSet<>();
		for (PhysicalObject object : environment.getOwnedObjects()) {
			if (object instanceof Group group) {
				List<Spot> spots = spotsBeside(group, followed);
				beside.put(group, spots);
				spots.stream().limit(Math.max(0, group.getCount() - 1)).forEach(spot -> followed.add(spot.floor()));
			}
		}
	}

	/**
	 * The places of an environment's crowds and groups.
	 *
	 * @param layout       the room's layout, as the generator lays it out (a map room in the map's frame)
	 * @param defaultHuman the type of people without one (the default catalogue's Human), or {@code null}: radius
	 *                     {@link #DEFAULT_RADIUS}
	 */
	public static PeoplePlacement of(Environment environment, FloorLayout layout, ObjectType defaultHuman) {
		return new PeoplePlacement(environment, layout, defaultHuman);
	}

	/**
	 * Who stands on each floor at the start of the run, the first the text names: furniture, the start of every
	 * moving object and person (a group's leader's), a crowd on each of its from floors, then the robot.
	 */
	public static Map<Floor, PhysicalObject> starts(Environment environment) {
		Map<Floor, PhysicalObject> starts = new LinkedHashMap<>();
		for (PhysicalObject object : environment.getOwnedObjects()) {
			if (object instanceof Crowd crowd) {
				crowd.getFrom().forEach(floor -> starts.putIfAbsent(floor, crowd));
			} else if (object.startFloor() != null) {
				starts.putIfAbsent(object.startFloor(), object);
			}
		}
		if (environment.getOwnedRobot() != null && environment.getOwnedRobot().getFloor() != null) {
			starts.putIfAbsent(environment.getOwnedRobot().getFloor(), environment.getOwnedRobot());
		}
		return starts;
	}

	/** Half the x size of the people's type (the default human's when it has none). */
	public double radius(PhysicalObject people) {
		ObjectType type = people.getType() != null && !people.getType().eIsProxy() ? people.getType() : defaultHuman;
		return type == null ? DEFAULT_RADIUS : type.getSizeX() / 2;
	}

	/** Who stands on a floor at the start of the run (the first the text names), or {@code null}. */
	public PhysicalObject startOn(Floor floor) {
		return starts.get(floor);
	}

	/** The places a crowd's people stand on at the start, in lattice order: person i on place i - 1. */
	public List<Spot> from(Crowd crowd) {
		return lattice(crowd.getFrom(), radius(crowd));
	}

	/** The places a crowd's people walk to, in lattice order: person i to place (i - 1) mod their number. */
	public List<Spot> to(Crowd crowd) {
		return lattice(crowd.getTo(), radius(crowd));
	}

	/**
	 * Every place a group's followers may stand on, nearest the leader first (equally near ones in lattice order):
	 * follower i (from 2) on place i - 2. Empty when the leader has no floor.
	 */
	public List<Spot> beside(Group group) {
		return beside.getOrDefault(group, List.of());
	}

	private List<Spot> spotsBeside(Group group, Set<Floor> followed) {
		Floor leader = group.startFloor();
		if (leader == null || leader.eIsProxy() || layout.cellOf(leader).isEmpty()) {
			return List.of();
		}
		List<Floor> area = new ArrayList<>(List.of(leader));
		for (Direction side : Direction.VALUES) {
			BuildingBlock next = layout.neighbour(leader, side);
			if (next instanceof Floor floor && !area.contains(floor) && !starts.containsKey(floor)
					&& !targets.contains(floor) && !followed.contains(floor)) {
				area.add(floor);
			}
		}
		double radius = radius(group);
		double spacing = 2 * radius + GAP;
		double[] centre = layout.centreOf(leader);
		List<Spot> spots = new ArrayList<>();
		for (Spot spot : lattice(area, radius)) {
			if (Math.hypot(spot.x() - centre[0], spot.y() - centre[1]) >= spacing - EPS) {
				spots.add(spot);
			}
		}
		// stable: equally near places (to the micrometre) stay in lattice order
		spots.sort(Comparator.comparingLong(s -> Math.round(Math.hypot(s.x() - centre[0], s.y() - centre[1]) * 1e6)));
		return spots;
	}

	/**
	 * The lattice points of an area for people of a radius, in rows from the bottom, each from the left. Floors
	 * without a place in the layout are left out.
	 */
	public List<Spot> lattice(Collection<Floor> floors, double radius) {
		double size = layout.floorSize();
		Map<Cell, Floor> area = new HashMap<>();
		double originX = 0;
		double originY = 0;
		int minX = Integer.MAX_VALUE;
		int minY = Integer.MAX_VALUE;
		for (Floor floor : floors) {
			Cell cell = floor == null ? null : layout.cellOf(floor).orElse(null);
			if (cell == null) {
				continue;
			}
			if (area.isEmpty()) {
				double[] centre = layout.centreOf(floor);
				originX = centre[0] - (cell.x() + 0.5) * size;
				originY = centre[1] - (cell.y() + 0.5) * size;
			}
			area.putIfAbsent(cell, floor);
			minX = Math.min(minX, cell.x());
			minY = Math.min(minY, cell.y());
		}
		if (area.isEmpty() || !(radius > 0) || !(size > 0)) {
			return List.of();
		}
		Area a = new Area(area, size, originX, originY, radius + CLEARANCE);
		double spacing = 2 * radius + GAP;
		double firstX = originX + minX * size + a.margin;
		double firstY = originY + minY * size + a.margin;
		// only points inside an area floor can be kept: enumerate those, row by row
		TreeSet<Long> points = new TreeSet<>();
		for (Cell cell : area.keySet()) {
			double x0 = originX + cell.x() * size;
			double y0 = originY + cell.y() * size;
			long iFrom = Math.max(0, (long) Math.ceil((x0 - firstX) / spacing - EPS));
			long iTo = (long) Math.floor((x0 + size - firstX) / spacing + EPS);
			long jFrom = Math.max(0, (long) Math.ceil((y0 - firstY) / spacing - EPS));
			long jTo = (long) Math.floor((y0 + size - firstY) / spacing + EPS);
			for (long j = jFrom; j <= jTo; j++) {
				for (long i = iFrom; i <= iTo; i++) {
					points.add(j << 32 | i);
				}
			}
		}
		List<Spot> spots = new ArrayList<>();
		for (long point : points) {
			double x = firstX + (point & 0xFFFFFFFFL) * spacing;
			double y = firstY + (point >>> 32) * spacing;
			Floor floor = a.covered(x, y);
			if (floor != null) {
				spots.add(new Spot(floor, x, y));
			}
		}
		return spots;
	}

	/** The cells of an area and what a disc on it must keep clear of. */
	private final class Area {
		final Map<Cell, Floor> cells;
		final double size;
		final double originX;
		final double originY;
		final double margin;

		Area(Map<Cell, Floor> cells, double size, double originX, double originY, double margin) {
			this.cells = cells;
			this.size = size;
			this.originX = originX;
			this.originY = originY;
			this.margin = margin;
		}

		/**
		 * The floor holding the point when the disc of {@link #margin} around it lies on the area's floors and
		 * crosses no wall between two of them (two floors side by side that are no neighbours), else {@code null}.
		 */
		Floor covered(double x, double y) {
			int fromX = (int) Math.floor((x - margin - originX) / size);
			int toX = (int) Math.floor((x + margin - originX) / size);
			int fromY = (int) Math.floor((y - margin - originY) / size);
			int toY = (int) Math.floor((y + margin - originY) / size);
			for (int cx = fromX; cx <= toX; cx++) {
				for (int cy = fromY; cy <= toY; cy++) {
					Floor floor = cells.get(new Cell(cx, cy));
					if (floor == null) {
						if (distance(x, y, cx, cy, cx + 1, cy + 1) < margin - EPS) {
							return null;
						}
						continue;
					}
					Floor right = cells.get(new Cell(cx + 1, cy));
					if (right != null && cx + 1 <= toX && !linked(floor, Direction.RIGHT, right, Direction.LEFT)
							&& distance(x, y, cx + 1, cy, cx + 1, cy + 1) < margin - EPS) {
						return null;
					}
					Floor top = cells.get(new Cell(cx, cy + 1));
					if (top != null && cy + 1 <= toY && !linked(floor, Direction.TOP, top, Direction.BOTTOM)
							&& distance(x, y, cx, cy + 1, cx + 1, cy + 1) < margin - EPS) {
						return null;
					}
				}
			}
			return cells.get(new Cell((int) Math.floor((x - originX) / size), (int) Math.floor((y - originY) / size)));
		}

		/** From a point to the rectangle (or segment) between two cell corners, in metres. */
		private double distance(double x, double y, int cx0, int cy0, int cx1, int cy1) {
			double dx = Math.max(Math.max(originX + cx0 * size - x, 0), x - (originX + cx1 * size));
			double dy = Math.max(Math.max(originY + cy0 * size - y, 0), y - (originY + cy1 * size));
			return Math.hypot(dx, dy);
		}

		private boolean linked(Floor a, Direction side, Floor b, Direction back) {
			return layout.neighbour(a, side) == b || layout.neighbour(b, back) == a;
		}
	}
}
