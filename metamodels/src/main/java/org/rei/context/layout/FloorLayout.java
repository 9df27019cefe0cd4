/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.layout;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.BuildingBlock;
import org.rei.context.ContextPackage;
import org.rei.context.Direction;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.OccupancyLayout;
import org.rei.context.Wall;

/**
 * Maps the floors of a room to grid cells and places its walls (thesis 6.2.1, Fig. 26; docs/artifacts.md
 * "Floor-to-coordinate mapping").
 * <p>
 * A breadth-first traversal from the start floor gives every floor a cell relative to its parent. Neighbour
 * references are followed in both directions; walls end a branch. Cells are then shifted so that the smallest x and
 * y are 0. Everything is linear in the number of floors: the benchmark lays out 10,000 of them.
 * <p>
 * A room from an occupancy map is not traversed: its floors are the map's free blocks, {@code F_x_y} at block
 * {@code (x, y)} from the map's origin, which may form several unconnected areas; its centres are in the map's frame
 * when the caller gives the origin ({@link #compute(Environment, ObjectType, double, double)}).
 * <p>
 * The result is immutable. When {@link #problems()} is not empty, cells and walls are what could be placed.
 */
public final class FloorLayout {

	/** Directions in the order they are visited, so that "the first floor that names a wall" is stable. */
	private static final Direction[] SIDES = { Direction.TOP, Direction.RIGHT, Direction.BOTTOM, Direction.LEFT };

	private final Environment environment;
	private final double floorSize;
	private final Floor start;
	private final Map<Floor, Cell> cells;
	private final Map<Floor, BuildingBlock[]> neighbours;
	private final List<WallPlacement> walls;
	private final Map<Wall, WallPlacement> wallIndex;
	private final List<LayoutProblem> problems;
	private final int columns;
	private final int rows;
	private final double originX;
	private final double originY;

	private FloorLayout(Builder b, double originX, double originY) {
		this.originX = originX;
		this.originY = originY;
		this.environment = b.environment;
		this.floorSize = b.environment.getFloorSize();
		this.start = b.start;
		this.cells = Collections.unmodifiableMap(b.cells);
		this.neighbours = b.neighbours;
		this.walls = Collections.unmodifiableList(b.walls);
		this.wallIndex = b.wallIndex;
		this.problems = Collections.unmodifiableList(b.problems);
		this.columns = b.columns;
		this.rows = b.rows;
	}

	/** Lays out the environment; walls without a type get the default catalogue's Wall. */
	public static FloorLayout compute(Environment env) {
		return compute(env, null);
	}

	/**
	 * Lays out the environment.
	 *
	 * @param defaultWallType type of walls that have none; {@code null} for the default catalogue's Wall
	 */
	public static FloorLayout compute(Environment env, ObjectType defaultWallType) {
		return compute(env, defaultWallType, 0, 0);
	}

	/**
	 * Lays out the environment with cell (0, 0)'s corner at {@code (originX, originY)}: an occupancy room's map
	 * origin.
	 *
	 * @param defaultWallType type of walls that have none; {@code null} for the default catalogue's Wall
	 */
	public static FloorLayout compute(Environment env, ObjectType defaultWallType, double originX, double originY) {
		return new Builder(env, defaultWallType).build(originX, originY);
	}

	/** The environment this layout was computed for. */
	public Environment environment() {
		return environment;
	}

	/** Edge length of a floor in metres. */
	public double floorSize() {
		return floorSize;
	}

	/** The floor the traversal started from: the robot's floor, else the first floor. */
	public Optional<Floor> start() {
		return Optional.ofNullable(start);
	}

	/** The cell of a floor, empty when it could not be placed (or is not a floor of this environment). */
	public Optional<Cell> cellOf(Floor floor) {
		return Optional.ofNullable(cells.get(floor));
	}

	/** Every placed floor with its cell, in model order. */
	public Map<Floor, Cell> cells() {
		return cells;
	}

	/**
	 * Centre of a floor's top surface as {@code [x, y]} in metres.
	 *
	 * @throws IllegalArgumentException when the floor has no cell
	 */
	public double[] centreOf(Floor floor) {
		Cell cell = cells.get(floor);
		if (cell == null) {
			throw new IllegalArgumentException("floor " + (floor == null ? null : floor.getName()) + " has no cell");
		}
		return new double[] { originX + (cell.x() + 0.5) * floorSize, originY + (cell.y() + 0.5) * floorSize };
	}

	/**
	 * The neighbour on one side of a floor: the declared one, else the floor that declares this floor on its
	 * opposite side, else {@code null} (an open side).
	 */
	public BuildingBlock neighbour(Floor floor, Direction side) {
		BuildingBlock[] sides = neighbours.get(floor);
		return sides == null ? null : sides[side.getValue()];
	}

	/** Placed walls in model order. */
	public List<WallPlacement> walls() {
		return walls;
	}

	/** Placement of one wall, empty when it has none. */
	public Optional<WallPlacement> placementOf(Wall wall) {
		return Optional.ofNullable(wallIndex.get(wall));
	}

	/** Why the room could not be laid out completely; empty when it could. */
	public List<LayoutProblem> problems() {
		return problems;
	}

	/** Whether every floor and wall has its place. */
	public boolean isValid() {
		return problems.isEmpty();
	}

	/** Number of cells along x (0 for a room without placed floors). */
	public int columns() {
		return columns;
	}

	/** Number of cells along y (0 for a room without placed floors). */
	public int rows() {
		return rows;
	}

	/** The neighbour reference of a side. */
	public static EReference feature(Direction side) {
		return switch (side) {
		case TOP -> ContextPackage.Literals.FLOOR__TOP;
		case RIGHT -> ContextPackage.Literals.FLOOR__RIGHT;
		case BOTTOM -> ContextPackage.Literals.FLOOR__BOTTOM;
		case LEFT -> ContextPackage.Literals.FLOOR__LEFT;
		};
	}

	private static BuildingBlock declared(Floor floor, Direction side) {
		return switch (side) {
		case TOP -> floor.getTop();
		case RIGHT -> floor.getRight();
		case BOTTOM -> floor.getBottom();
		case LEFT -> floor.getLeft();
		};
	}

	private static int dx(Direction side) {
		return side == Direction.RIGHT ? 1 : side == Direction.LEFT ? -1 : 0;
	}

	private static int dy(Direction side) {
		return side == Direction.TOP ? 1 : side == Direction.BOTTOM ? -1 : 0;
	}

	private static Direction opposite(Direction side) {
		return SIDES[(side.getValue() + 2) % 4];
	}

	/** Lazily loaded once: most test cases leave wall types implicit. */
	private static final class DefaultWall {
		static final ObjectType TYPE = Catalogues.find(Catalogues.loadDefault(new ResourceSetImpl()), "Wall")
				.orElseThrow(() -> new IllegalStateException("default catalogue has no Wall type"));
	}

	/** A traversable edge; {@code declaring.feature} is the reference it comes from (for error reports). */
	private record Link(int target, int dx, int dy, Floor declaring, EReference feature, int reference) {
	}

	/** One-shot computation state, kept out of the immutable result. */
	private static final class Builder {
		final Environment environment;
		final ObjectType defaultWallType;
		final List<Floor> floors = new ArrayList<>();
		final List<Wall> wallList = new ArrayList<>();
		final Map<Floor, Integer> floorIndex = new HashMap<>();
		final Set<Wall> wallSet = new HashSet<>();
		final Map<Floor, BuildingBlock[]> neighbours = new HashMap<>();
		final Map<Floor, Cell> cells = new LinkedHashMap<>();
		final List<WallPlacement> walls = new ArrayList<>();
		final Map<Wall, WallPlacement> wallIndex = new HashMap<>();
		final List<LayoutProblem> problems = new ArrayList<>();
		Floor start;
		int columns;
		int rows;

		Builder(Environment environment, ObjectType defaultWallType) {
			this.environment = environment;
			this.defaultWallType = defaultWallType;
		}

		FloorLayout build(double originX, double originY) {
			for (BuildingBlock block : environment.getOwnedBlocks()) {
				if (block instanceof Floor floor) {
					floorIndex.put(floor, floors.size());
					floors.add(floor);
				} else if (block instanceof Wall wall) {
					wallList.add(wall);
					wallSet.add(wall);
				}
			}
			if (!floors.isEmpty()) {
				start = startFloor();
				if (environment.getOwnedLayout() instanceof OccupancyLayout) {
					placeMapFloors();
				} else {
					placeFloors(links());
				}
				placeWalls();
			}
			reportOrphanWalls();
			return new FloorLayout(this, originX, originY);
		}

		/**
		 * The floors of an occupancy room are at their blocks of the map (their names say which); the map names
		 * every neighbour on both sides, so there is nothing to traverse or infer.
		 */
		private void placeMapFloors() {
			for (Floor floor : floors) {
				BuildingBlock[] sides = new BuildingBlock[4];
				for (Direction side : SIDES) {
					sides[side.getValue()] = declared(floor, side);
				}
				neighbours.put(floor, sides);
				var block = MapFiles.blockOf(floor);
				if (block.isEmpty()) {
					problems.add(new LayoutProblem(floor, null, LayoutIssueCodes.DISCONNECTED,
							"floor " + floor.getName() + " is no block F_x_y of the room's map"));
					continue;
				}
				cells.put(floor, block.get());
				columns = Math.max(columns, block.get().x() + 1);
				rows = Math.max(rows, block.get().y() + 1);
			}
		}

		private Floor startFloor() {
			var robot = environment.getOwnedRobot();
			if (robot != null && robot.getFloor() != null && floorIndex.containsKey(robot.getFloor())) {
				return robot.getFloor();
			}
			return floors.get(0);
		}

		/** Adjacency lists with every floor-to-floor reference in both directions; also fills {@link #neighbours}. */
		@SuppressWarnings("unchecked")
		private List<Link>[] links() {
			int n = floors.size();
			List<Link>[] links = new List[n];
			for (int i = 0; i < n; i++) {
				links[i] = new ArrayList<>(4);
				BuildingBlock[] sides = new BuildingBlock[4];
				Floor floor = floors.get(i);
				for (Direction side : SIDES) {
					sides[side.getValue()] = declared(floor, side);
				}
				neighbours.put(floor, sides);
			}
			for (int i = 0; i < n; i++) {
				Floor floor = floors.get(i);
				for (Direction side : SIDES) {
					if (!(declared(floor, side) instanceof Floor other)) {
						continue; // open side or wall: the branch ends here
					}
					Integer j = floorIndex.get(other);
					if (j == null) {
						continue; // a floor of another environment: scoping reports it, not the layout
					}
					EReference feature = feature(side);
					int reference = 4 * i + side.getValue();
					links[i].add(new Link(j, dx(side), dy(side), floor, feature, reference));
					links[j].add(new Link(i, -dx(side), -dy(side), floor, feature, reference));
					BuildingBlock[] back = neighbours.get(other);
					int opposite = opposite(side).getValue();
					if (back[opposite] == null) {
						back[opposite] = floor; // declared only on one side: infer the other
					}
				}
			}
			return links;
		}

		private void placeFloors(List<Link>[] links) {
			int n = floors.size();
			int[] xs = new int[n];
			int[] ys = new int[n];
			boolean[] placed = new boolean[n];
			boolean[] reported = new boolean[4 * n]; // one report per reference, not per direction it is followed
			ArrayDeque<Integer> queue = new ArrayDeque<>();
			int s = floorIndex.get(start);
			placed[s] = true;
			queue.add(s);
			while (!queue.isEmpty()) {
				int f = queue.poll();
				for (Link link : links[f]) {
					int x = xs[f] + link.dx();
					int y = ys[f] + link.dy();
					int t = link.target();
					if (!placed[t]) {
						placed[t] = true;
						xs[t] = x;
						ys[t] = y;
						queue.add(t);
					} else if ((xs[t] != x || ys[t] != y) && !reported[link.reference()]) {
						reported[link.reference()] = true;
						Floor target = floors.get(t);
						problems.add(new LayoutProblem(link.declaring(), link.feature(), LayoutIssueCodes.INCONSISTENT_LOOP,
								"floor " + target.getName() + " is reached at two different places, " + new Cell(xs[t], ys[t])
										+ " and " + new Cell(x, y) + " relative to " + start.getName()
										+ ": the neighbour references form an inconsistent loop"));
					}
				}
			}
			int minX = Integer.MAX_VALUE;
			int minY = Integer.MAX_VALUE;
			int maxX = Integer.MIN_VALUE;
			int maxY = Integer.MIN_VALUE;
			for (int i = 0; i < n; i++) {
				if (placed[i]) {
					minX = Math.min(minX, xs[i]);
					minY = Math.min(minY, ys[i]);
					maxX = Math.max(maxX, xs[i]);
					maxY = Math.max(maxY, ys[i]);
				}
			}
			columns = maxX - minX + 1;
			rows = maxY - minY + 1;
			Map<Cell, Floor> occupied = new HashMap<>(n * 2);
			for (int i = 0; i < n; i++) {
				Floor floor = floors.get(i);
				if (!placed[i]) {
					problems.add(new LayoutProblem(floor, null, LayoutIssueCodes.DISCONNECTED,
							"floor " + floor.getName() + " is not connected to the start floor " + start.getName()
									+ " through neighbour references"));
					continue;
				}
				Cell cell = new Cell(xs[i] - minX, ys[i] - minY);
				Floor other = occupied.putIfAbsent(cell, floor);
				if (other != null) {
					problems.add(new LayoutProblem(floor, null, LayoutIssueCodes.OVERLAP,
							"floors " + other.getName() + " and " + floor.getName() + " are both at cell " + cell));
				}
				cells.put(floor, cell);
			}
		}

		private void placeWalls() {
			double size = environment.getFloorSize();
			// edge of a side in half-cell units: equal keys mean the same place (parity tells the orientation)
			Map<Wall, Cell> edges = new HashMap<>();
			Map<Wall, WallPlacement> first = new HashMap<>();
			for (Map.Entry<Floor, Cell> entry : cells.entrySet()) {
				Floor floor = entry.getKey();
				Cell cell = entry.getValue();
				for (Direction side : SIDES) {
					if (!(declared(floor, side) instanceof Wall wall) || !wallSet.contains(wall)) {
						continue;
					}
					Cell edge = new Cell(2 * cell.x() + 1 + dx(side), 2 * cell.y() + 1 + dy(side));
					Cell known = edges.putIfAbsent(wall, edge);
					if (known == null) {
						first.put(wall, place(wall, floor, cell, side, size));
					} else if (!known.equals(edge)) {
						WallPlacement p = first.get(wall);
						problems.add(new LayoutProblem(floor, feature(side), LayoutIssueCodes.WALL_CONFLICT,
								"wall " + wall.getName() + " is named by " + p.floor().getName() + " (" + p.side().getLiteral()
										+ ") and by " + floor.getName() + " (" + side.getLiteral()
										+ "), which are different places"));
					}
				}
			}
			for (Wall wall : wallList) {
				WallPlacement p = first.get(wall);
				if (p != null) {
					walls.add(p);
					wallIndex.put(wall, p);
				}
			}
		}

		private WallPlacement place(Wall wall, Floor floor, Cell cell, Direction side, double size) {
			ObjectType type = wall.getType() != null ? wall.getType()
					: defaultWallType != null ? defaultWallType : DefaultWall.TYPE;
			double t = type.getSizeY();
			double h = type.getSizeZ();
			double x = (cell.x() + 0.5 + 0.5 * dx(side)) * size;
			double y = (cell.y() + 0.5 + 0.5 * dy(side)) * size;
			boolean alongX = side == Direction.TOP || side == Direction.BOTTOM;
			// length floorSize + t so that the walls of neighbouring floors meet at the corners
			return new WallPlacement(wall, floor, side, type, x, y, h / 2, alongX ? size + t : t, alongX ? t : size + t,
					h);
		}

		private void reportOrphanWalls() {
			Set<Wall> named = new HashSet<>();
			for (Floor floor : floors) {
				for (Direction side : SIDES) {
					if (declared(floor, side) instanceof Wall wall) {
						named.add(wall);
					}
				}
			}
			for (Wall wall : wallList) {
				if (!named.contains(wall)) {
					problems.add(new LayoutProblem(wall, null, LayoutIssueCodes.ORPHAN_WALL,
							"wall " + wall.getName() + " is not the neighbour of any floor, so it has no place"));
				}
			}
		}
	}
}
