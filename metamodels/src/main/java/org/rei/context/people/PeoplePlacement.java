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
import org.rei.catalogue.Shape;
import org.rei.context.BuildingBlock;
import org.rei.context.Crowd;
import org.rei.context.Direction;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.PhysicalObject;
import org.rei.context.StaticObject;
import org.rei.context.Wall;
import org.rei.context.layout.Cell;
import org.rei.context.layout.FloorLayout;
import org.rei.context.layout.WallPlacement;

/**
 * Where the people of crowds and groups stand and where a crowd's people walk to (docs/language.md, "Crowds and
 * groups"); the validator counts what it finds, the generator places the people on it, so both agree.
 * <p>
 * An <b>area</b> (a set of floors) holds the points of a square lattice of spacing {@code 2 * radius + 0.1} m: the
 * first point {@code radius + 0.05} m in from the bottom-left corner of the area's bounding box (from the inner
 * face of a wall along its left or bottom side: a wall stands half on its floor), the points in rows from the
 * bottom, each row from the left. A point is kept when its disc of {@code radius + 0.05} m lies on the area's floors
 * and touches no wall and no furniture's footprint (the simulation's walkable area, docs/people.md), so people of
 * that radius stand 0.1 m apart and 0.05 m in from the area's edge: the people server refuses anyone nearer to a
 * wall than its radius. A crowd's {@link #from} and {@link #to} areas are its floors; a group's followers stand on
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

	private final Environment environment;
	private final FloorLayout layout;
	private final ObjectType defaultHuman;
	private final Map<Floor, PhysicalObject> starts = new LinkedHashMap<>();
	private final Set<Floor> targets = new HashSet<>();
	private final Map<Group, List<Spot>> beside = new IdentityHashMap<>();

	private PeoplePlacement(Environment environment, FloorLayout layout, ObjectType defaultHuman) {
		this.environment = environment;
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
		}
		if (area.isEmpty() || !(radius > 0) || !(size > 0)) {
			return List.of();
		}
		double margin = radius + CLEARANCE;
		double spacing = 2 * radius + GAP;
		// the bounding box of the floors less the walls along their sides: a wall stands half on its floor
		double left = Double.POSITIVE_INFINITY;
		double bottom = Double.POSITIVE_INFINITY;
		double right = Double.NEGATIVE_INFINITY;
		double top = Double.NEGATIVE_INFINITY;
		for (Map.Entry<Cell, Floor> e : area.entrySet()) {
			double x0 = originX + e.getKey().x() * size;
			double y0 = originY + e.getKey().y() * size;
			left = Math.min(left, Math.max(x0, face(e.getValue(), Direction.LEFT, originX, originY)));
			bottom = Math.min(bottom, Math.max(y0, face(e.getValue(), Direction.BOTTOM, originX, originY)));
			right = Math.max(right, x0 + size);
			top = Math.max(top, y0 + size);
		}
		Area a = new Area(area, size, originX, originY, margin, obstacles(left - margin, bottom - margin,
				right + margin, top + margin, originX, originY));
		double firstX = left + margin;
		double firstY = bottom + margin;
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

	/**
	 * Where the inner face of the wall on a side of a floor is (x for LEFT, y for BOTTOM), or minus infinity when no
	 * wall stands there.
	 */
	private double face(Floor floor, Direction side, double originX, double originY) {
		if (!(layout.neighbour(floor, side) instanceof Wall wall)) {
			return Double.NEGATIVE_INFINITY;
		}
		return layout.placementOf(wall).map(p -> side == Direction.LEFT ? originX + p.x() + p.sizeX() / 2
				: originY + p.y() + p.sizeY() / 2).orElse(Double.NEGATIVE_INFINITY);
	}

	/**
	 * What people cannot stand in, as the simulation's walkable area leaves it out: the walls and the furniture's
	 * footprints (turned by their yaw), those that reach into a box.
	 */
	private List<Obstacle> obstacles(double minX, double minY, double maxX, double maxY, double originX,
			double originY) {
		List<Obstacle> near = new ArrayList<>();
		for (WallPlacement wall : layout.walls()) {
			Obstacle o = new Obstacle(originX + wall.x(), originY + wall.y(), wall.sizeX() / 2, wall.sizeY() / 2, 0,
					false);
			if (o.reaches(minX, minY, maxX, maxY)) {
				near.add(o);
			}
		}
		for (PhysicalObject object : environment.getOwnedObjects()) {
			if (!(object instanceof StaticObject) || object.getFloor() == null || object.getType() == null
					|| object.getType().eIsProxy() || layout.cellOf(object.getFloor()).isEmpty()) {
				continue;
			}
			ObjectType type = object.getType();
			double[] centre = layout.centreOf(object.getFloor());
			boolean disc = type.getShape() == Shape.CYLINDER;
			Obstacle o = new Obstacle(centre[0], centre[1], type.getSizeX() / 2,
					(disc ? type.getSizeX() : type.getSizeY()) / 2, Math.toRadians(object.getYaw()), disc);
			if (o.reaches(minX, minY, maxX, maxY)) {
				near.add(o);
			}
		}
		return near;
	}

	/** A box of half sizes hx, hy turned by yaw about its centre, or a disc of radius hx. */
	private record Obstacle(double x, double y, double hx, double hy, double yaw, boolean disc) {

		double distance(double px, double py) {
			double dx = px - x;
			double dy = py - y;
			if (disc) {
				return Math.max(0, Math.hypot(dx, dy) - hx);
			}
			double c = Math.cos(yaw);
			double s = Math.sin(yaw);
			double u = Math.abs(c * dx + s * dy) - hx;
			double v = Math.abs(-s * dx + c * dy) - hy;
			return Math.hypot(Math.max(u, 0), Math.max(v, 0));
		}

		/** Whether it may reach into the box (by its circumscribed circle). */
		boolean reaches(double minX, double minY, double maxX, double maxY) {
			double r = Math.hypot(hx, disc ? 0 : hy);
			return x + r >= minX && x - r <= maxX && y + r >= minY && y - r <= maxY;
		}
	}

	/** The cells of an area and what a disc on it must keep clear of. */
	private static final class Area {
		final Map<Cell, Floor> cells;
		final double size;
		final double originX;
		final double originY;
		final double margin;
		final List<Obstacle> obstacles;

		Area(Map<Cell, Floor> cells, double size, double originX, double originY, double margin,
				List<Obstacle> obstacles) {
			this.cells = cells;
			this.size = size;
			this.originX = originX;
			this.originY = originY;
			this.margin = margin;
			this.obstacles = obstacles;
		}

		/**
		 * The floor holding the point when the disc of {@link #margin} around it lies on the area's floors and
		 * touches no wall and no furniture, else {@code null}.
		 */
		Floor covered(double x, double y) {
			int fromX = (int) Math.floor((x - margin - originX) / size);
			int toX = (int) Math.floor((x + margin - originX) / size);
			int fromY = (int) Math.floor((y - margin - originY) / size);
			int toY = (int) Math.floor((y + margin - originY) / size);
			for (int cx = fromX; cx <= toX; cx++) {
				for (int cy = fromY; cy <= toY; cy++) {
					if (!cells.containsKey(new Cell(cx, cy)) && distance(x, y, cx, cy) < margin - EPS) {
						return null;
					}
				}
			}
			for (Obstacle obstacle : obstacles) {
				if (obstacle.distance(x, y) < margin - EPS) {
					return null;
				}
			}
			return cells.get(new Cell((int) Math.floor((x - originX) / size), (int) Math.floor((y - originY) / size)));
		}

		/** From a point to a cell, in metres. */
		private double distance(double x, double y, int cx, int cy) {
			double dx = Math.max(Math.max(originX + cx * size - x, 0), x - (originX + (cx + 1) * size));
			double dy = Math.max(Math.max(originY + cy * size - y, 0), y - (originY + (cy + 1) * size));
			return Math.hypot(dx, dy);
		}
	}
}
