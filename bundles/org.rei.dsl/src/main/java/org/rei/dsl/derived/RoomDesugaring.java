/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.derived;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.rei.context.AsciiLayout;
import org.rei.context.BuildingBlock;
import org.rei.context.ContextFactory;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.GridLayout;
import org.rei.context.Layout;
import org.rei.context.OccupancyLayout;
import org.rei.context.Wall;
import org.rei.context.layout.FloorLayout;
import org.rei.context.layout.MapFiles;
import org.rei.maps.FloorBlocks;
import org.rei.maps.MapBlocks;
import org.rei.maps.MapCache;
import org.rei.maps.MapException;
import org.rei.maps.OccupancyMap;

/**
 * Turns a compact room description into the explicit floor graph of the context metamodel: floor F_x_y on every
 * cell (x from the left, y from the bottom) with its neighbours, and a wall W_x_y_side on every side that borders
 * no floor. A room from an occupancy map gets a floor F_x_y on every free block of the map (x, y counted from the map's
 * origin) and no walls: the map's obstacle cells are its walls, which the generator places.
 */
public final class RoomDesugaring {

	/** Map characters that are not floors; everything else that is not blank is a floor. */
	static final char WALL_CHAR = '#';

	/**
	 * The most cells a size or a drawn map may span (200 x 200): beyond it nothing is derived and the validator
	 * reports the room as too large, instead of allocating by a number from the text (size 100000 x 100000 would
	 * need 10^10 cells).
	 */
	public static final long MAX_CELLS = 40_000;

	/**
	 * The most floors a room from an occupancy map may have (free blocks; the map's size is not limited): about
	 * 125 x 125 m of 0.25 m floors. Each floor is a model element the editor and the generator hold, so beyond
	 * it nothing is derived and the validator asks for larger floors.
	 */
	public static final int MAX_MAP_FLOORS = 250_000;

	private RoomDesugaring() {
	}

	public static List<BuildingBlock> blocksOf(Layout layout) {
		if (tooLarge(layout)) {
			return List.of();
		}
		if (layout instanceof GridLayout grid) {
			return build(fullGrid(grid.getColumns(), grid.getRows()));
		}
		if (layout instanceof AsciiLayout ascii) {
			return build(cellsOf(ascii.getMap()));
		}
		if (layout instanceof OccupancyLayout occupancy) {
			return blocksOf(occupancy);
		}
		return List.of();
	}

	/**
	 * The free blocks of the room's map; none when the map cannot be read, the floor size is not positive or cuts
	 * the map into too many blocks, or there are more than {@link #MAX_MAP_FLOORS} (the validator reports each).
	 */
	private static List<BuildingBlock> blocksOf(OccupancyLayout layout) {
		Optional<FloorBlocks> found = freeBlocks(layout);
		if (found.isEmpty() || found.get().freeCount() > MAX_MAP_FLOORS) {
			return List.of();
		}
		FloorBlocks blocks = found.get();
		boolean[][] cells = new boolean[blocks.columns()][blocks.rows()];
		for (int x = 0; x < blocks.columns(); x++) {
			for (int y = 0; y < blocks.rows(); y++) {
				cells[x][y] = blocks.isFree(x, y);
			}
		}
		return build(cells, false);
	}

	/**
	 * The layout of a room in the world frame: for a room from an occupancy map, cell (0, 0)'s corner at the map's
	 * origin (world frame = map frame), as the generator places it.
	 */
	public static FloorLayout layoutOf(Environment environment) {
		if (environment.getOwnedLayout() instanceof OccupancyLayout occupancy) {
			try {
				OccupancyMap map = mapOf(occupancy);
				return FloorLayout.compute(environment, null, map.originX(), map.originY());
			} catch (MapException e) {
				// no map, no floors: the validator reports it
			}
		}
		return FloorLayout.compute(environment);
	}

	/** The room's map, read once per version of its files ({@link MapCache}). */
	public static OccupancyMap mapOf(OccupancyLayout layout) throws MapException {
		Path yaml = MapFiles.yamlOf(layout).orElseThrow(() -> new MapException(Path.of(String.valueOf(layout.getMap())),
				1, 1, "file", "not a file path"));
		return MapCache.get(yaml);
	}

	/**
	 * The floor blocks of an occupancy room, empty when its map cannot be read, its floor size is not positive or
	 * cuts the map into more than {@link MapBlocks#MAX_BLOCKS} blocks (counted before anything is allocated; the
	 * validator reports each).
	 */
	public static Optional<FloorBlocks> freeBlocks(OccupancyLayout layout) {
		if (!(layout.eContainer() instanceof Environment environment) || !(environment.getFloorSize() > 0)) {
			return Optional.empty();
		}
		try {
			OccupancyMap map = mapOf(layout);
			if (MapBlocks.tooManyBlocks(MapBlocks.blockGrid(map, environment.getFloorSize()))) {
				return Optional.empty();
			}
			return Optional.of(map.floorBlocks(environment.getFloorSize(), layout.isUnknownFree()));
		} catch (MapException e) {
			return Optional.empty();
		}
	}

	/** Whether the layout spans more than {@link #MAX_CELLS} cells (then it derives nothing). */
	public static boolean tooLarge(Layout layout) {
		if (layout instanceof GridLayout grid) {
			return (long) grid.getColumns() * grid.getRows() > MAX_CELLS;
		}
		if (layout instanceof AsciiLayout ascii && ascii.getMap() != null) {
			List<String> lines = ascii.getMap().lines().toList();
			long width = lines.stream().mapToInt(String::length).max().orElse(0);
			return width * lines.size() > MAX_CELLS;
		}
		return false;
	}

	/** Metres as a message writes them: {@code 1}, {@code 0.25}. */
	public static String metres(double value) {
		return java.math.BigDecimal.valueOf(value).stripTrailingZeros().toPlainString();
	}

	public static String floorName(int x, int y) {
		return "F_" + x + "_" + y;
	}

	public static String wallName(int x, int y, String side) {
		return "W_" + x + "_" + y + "_" + side;
	}

	private static boolean[][] fullGrid(int columns, int rows) {
		boolean[][] cells = new boolean[Math.max(columns, 0)][Math.max(rows, 0)];
		for (boolean[] column : cells) {
			java.util.Arrays.fill(column, true);
		}
		return cells;
	}

	/**
	 * Cells of a drawn map, indexed [x][y]: the bottom line is row 0, and the drawing is cropped to its floors so
	 * that the bottom-left floor is F_0_0 whatever border is drawn around it.
	 */
	static boolean[][] cellsOf(String map) {
		List<String> lines = map == null ? List.of() : map.lines().toList();
		int height = lines.size();
		int width = lines.stream().mapToInt(String::length).max().orElse(0);
		int minX = Integer.MAX_VALUE, minY = Integer.MAX_VALUE, maxX = -1, maxY = -1;
		boolean[][] drawn = new boolean[width][height];
		for (int row = 0; row < height; row++) {
			String line = lines.get(row);
			int y = height - 1 - row;
			for (int x = 0; x < line.length(); x++) {
				char c = line.charAt(x);
				if (!Character.isWhitespace(c) && c != WALL_CHAR) {
					drawn[x][y] = true;
					minX = Math.min(minX, x);
					maxX = Math.max(maxX, x);
					minY = Math.min(minY, y);
					maxY = Math.max(maxY, y);
				}
			}
		}
		if (maxX < 0) {
			return new boolean[0][0];
		}
		boolean[][] cells = new boolean[maxX - minX + 1][maxY - minY + 1];
		for (int x = minX; x <= maxX; x++) {
			for (int y = minY; y <= maxY; y++) {
				cells[x - minX][y - minY] = drawn[x][y];
			}
		}
		return cells;
	}

	private static List<BuildingBlock> build(boolean[][] cells) {
		return build(cells, true);
	}

	/** Floors on the true cells with their neighbours; {@code walled}: a wall on every side that borders no floor. */
	private static List<BuildingBlock> build(boolean[][] cells, boolean walled) {
		int width = cells.length;
		int height = width == 0 ? 0 : cells[0].length;
		Floor[][] floors = new Floor[width][height];
		List<BuildingBlock> blocks = new ArrayList<>();
		for (int y = 0; y < height; y++) {
			for (int x = 0; x < width; x++) {
				if (cells[x][y]) {
					// marked once built: an element without adapters sends no notifications, which for 100,000s
					// of floors is most of the work
					Floor floor = ContextFactory.eINSTANCE.createFloor();
					floor.setName(floorName(x, y));
					floors[x][y] = floor;
					blocks.add(floor);
				}
			}
		}
		List<BuildingBlock> walls = new ArrayList<>();
		for (int y = 0; y < height; y++) {
			for (int x = 0; x < width; x++) {
				Floor floor = floors[x][y];
				if (floor == null) {
					continue;
				}
				List<BuildingBlock> sideWalls = walled ? walls : null;
				floor.setTop(neighbour(floors, x, y + 1, x, y, "top", sideWalls));
				floor.setRight(neighbour(floors, x + 1, y, x, y, "right", sideWalls));
				floor.setBottom(neighbour(floors, x, y - 1, x, y, "bottom", sideWalls));
				floor.setLeft(neighbour(floors, x - 1, y, x, y, "left", sideWalls));
			}
		}
		blocks.addAll(walls);
		blocks.forEach(DerivedMarker::mark);
		return blocks;
	}

	private static BuildingBlock neighbour(Floor[][] floors, int nx, int ny, int x, int y, String side,
			List<BuildingBlock> walls) {
		boolean inside = nx >= 0 && ny >= 0 && nx < floors.length && ny < floors[nx].length;
		if (inside && floors[nx][ny] != null) {
			return floors[nx][ny];
		}
		if (walls == null) {
			return null; // an open side
		}
		Wall wall = ContextFactory.eINSTANCE.createWall();
		wall.setName(wallName(x, y, side));
		walls.add(wall);
		return wall;
	}
}
