/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

/**
 * What a room makes of an occupancy map, the very algorithm of the Python side's {@code rei.maps.blocks} (so that
 * both sides name the same rectangles and floors): a cell is an obstacle when occupied (100) and, unless
 * {@code unknownFree}, when unknown (-1); every other value is free, as Nav2's static layer reads them. A floor block
 * is free when every cell it overlaps is free; blocks count from the map's origin and only blocks wholly inside the
 * map exist.
 */
public final class MapBlocks {

	/** A millionth of a cell, so that 1.0 m over 0.05 m cells is 20 cells, not 20.000000000000004. */
	private static final double EPS = 1e-6;

	private MapBlocks() {
	}

	/** {@code height * width} booleans, row 0 at the bottom: the cells a robot may not enter. */
	public static boolean[] obstacleMask(OccupancyMap map, boolean unknownFree) {
		int w = map.width();
		int h = map.height();
		boolean[] mask = new boolean[w * h];
		for (int row = 0; row < h; row++) {
			for (int col = 0; col < w; col++) {
				byte v = map.cell(col, row);
				mask[row * w + col] = v == OccupancyMap.OCCUPIED || (!unknownFree && v == OccupancyMap.UNKNOWN);
			}
		}
		return mask;
	}

	/**
	 * Disjoint rectangles covering exactly the true cells of {@code mask}: each row's runs, stacked while the next
	 * row has the very same run; done along rows and along columns, the fewer kept (along rows on a tie).
	 */
	public static List<CellRect> mergeRectangles(boolean[] mask, int width, int height) {
		List<CellRect> byRows = stackRuns(mask, width, height, false);
		List<CellRect> byCols = stackRuns(mask, height, width, true);
		return byRows.size() <= byCols.size() ? byRows : byCols;
	}

	/**
	 * Runs of each line stacked into rectangles, sorted by (first line, first cell) of the scanned orientation.
	 * {@code transposed}: lines are the mask's columns (then the rectangles are turned back).
	 */
	private static List<CellRect> stackRuns(boolean[] mask, int lineLength, int lines, boolean transposed) {
		int width = transposed ? lines : lineLength;
		List<int[]> done = new ArrayList<>(); // {start, line, length, lineCount} in scan coordinates
		Map<Long, Integer> open = new HashMap<>(); // (start, end) -> first line
		Map<Long, Integer> current = new HashMap<>();
		for (int line = 0; line <= lines; line++) {
			current.clear();
			if (line < lines) {
				int at = 0;
				while (at < lineLength) {
					if (!at(mask, width, transposed, line, at)) {
						at++;
						continue;
					}
					int start = at;
					while (at < lineLength && at(mask, width, transposed, line, at)) {
						at++;
					}
					current.put(key(start, at), line);
				}
			}
			for (Iterator<Map.Entry<Long, Integer>> it = open.entrySet().iterator(); it.hasNext();) {
				Map.Entry<Long, Integer> run = it.next();
				if (!current.containsKey(run.getKey())) {
					int start = (int) (run.getKey() >>> 32);
					int end = (int) (long) run.getKey();
					done.add(new int[] { start, run.getValue(), end - start, line - run.getValue() });
					it.remove();
				}
			}
			for (Long run : current.keySet()) {
				open.putIfAbsent(run, line);
			}
		}
		done.sort(Comparator.<int[]>comparingInt(r -> r[1]).thenComparingInt(r -> r[0]));
		List<CellRect> rects = new ArrayList<>(done.size());
		for (int[] r : done) {
			rects.add(transposed ? new CellRect(r[1], r[0], r[3], r[2]) : new CellRect(r[0], r[1], r[2], r[3]));
		}
		return rects;
	}

	private static boolean at(boolean[] mask, int width, boolean transposed, int line, int index) {
		return transposed ? mask[index * width + line] : mask[line * width + index];
	}

	private static long key(int start, int end) {
		return ((long) start << 32) | end;
	}

	/**
	 * The most blocks of {@code floorSize} (free or not, columns x rows) a map may be cut into: 4,000,000, 16 times
	 * the floors a room from a map may have, e.g. an 8,000 x 8,000 cell map (400 x 400 m at 0.05 m) in 0.2 m
	 * blocks. A floor size far below the map's resolution would otherwise ask for more blocks than memory holds
	 * (0.0000001 m over 10 x 6 m: 6 * 10^15). The Python side's {@code rei.maps.MAX_BLOCKS} is the same number:
	 * both are copies of {@code maps.max_blocks} in contract/vocabulary.json.
	 */
	public static final long MAX_BLOCKS = 4_000_000L;

	/**
	 * The blocks of {@code floorSize} metres the map is cut into, {@code {columns, rows}} (only blocks wholly inside
	 * the map), as whole numbers in doubles: they never overflow, however small the floor size (infinite at worst).
	 */
	public static double[] blockGrid(OccupancyMap map, double floorSize) {
		return new double[] { Math.floor(map.width() * map.resolution() / floorSize + EPS),
				Math.floor(map.height() * map.resolution() / floorSize + EPS) };
	}

	/** Whether {@code grid} ({@link #blockGrid}) has more than {@link #MAX_BLOCKS} blocks. */
	public static boolean tooManyBlocks(double[] grid) {
		return grid[0] * grid[1] > MAX_BLOCKS; // doubles: 10^8 x 10^8 is 10^16, not a wrapped int
	}

	/** A count of {@link #blockGrid}: its digits, or {@code 1e+300} when beyond any integer type. */
	public static String count(double value) {
		return value < 1e15 ? String.valueOf((long) value) : MapReader.g(value);
	}

	/**
	 * Which {@code floorSize} blocks of the map are free (every cell they overlap is free).
	 *
	 * @throws IllegalArgumentException for a floor size that is not above 0, or that cuts the map into more than
	 *             {@link #MAX_BLOCKS} blocks (checked before anything is allocated)
	 */
	public static FloorBlocks floorBlocks(OccupancyMap map, double floorSize, boolean unknownFree) {
		if (!(floorSize > 0)) {
			throw new IllegalArgumentException("floor size " + floorSize + ": expected metres above 0");
		}
		double[] grid = blockGrid(map, floorSize);
		if (tooManyBlocks(grid)) {
			throw new IllegalArgumentException("floor size " + MapReader.g(floorSize) + " m cuts the map's "
					+ map.width() + " x " + map.height() + " cells of " + MapReader.g(map.resolution()) + " m into "
					+ count(grid[0]) + " x " + count(grid[1]) + " blocks: at most " + MAX_BLOCKS
					+ " (free or not); use a larger floor size");
		}
		int w = map.width();
		int h = map.height();
		boolean[] blocked = obstacleMask(map, unknownFree);
		double res = map.resolution();
		// no row of blocks, no block: a long thin map's columns alone may not be counted out
		int nx = grid[1] == 0 ? 0 : (int) grid[0];
		int ny = grid[0] == 0 ? 0 : (int) grid[1];
		// summed-area table of the blocked cells: any block's count in four lookups (ints: a map has at most
		// OccupancyMap.MAX_CELLS cells, far below 2^31)
		int[] table = new int[(h + 1) * (w + 1)];
		for (int row = 0; row < h; row++) {
			int sum = 0;
			for (int col = 0; col < w; col++) {
				sum += blocked[row * w + col] ? 1 : 0;
				table[(row + 1) * (w + 1) + col + 1] = table[row * (w + 1) + col + 1] + sum;
			}
		}
		int[] x0 = low(nx, floorSize, res);
		int[] x1 = high(nx, floorSize, res, w);
		int[] y0 = low(ny, floorSize, res);
		int[] y1 = high(ny, floorSize, res, h);
		int[] obstacles = new int[nx * ny];
		int[] columnCells = new int[nx];
		int[] rowCells = new int[ny];
		for (int x = 0; x < nx; x++) {
			columnCells[x] = x1[x] - x0[x];
		}
		for (int y = 0; y < ny; y++) {
			rowCells[y] = y1[y] - y0[y];
			for (int x = 0; x < nx; x++) {
				obstacles[y * nx + x] = table[y1[y] * (w + 1) + x1[x]] - table[y0[y] * (w + 1) + x1[x]]
						- table[y1[y] * (w + 1) + x0[x]] + table[y0[y] * (w + 1) + x0[x]];
			}
		}
		return new FloorBlocks(floorSize, nx, ny, obstacles, columnCells, rowCells);
	}

	private static int[] low(int count, double floorSize, double res) {
		int[] low = new int[count];
		for (int i = 0; i < count; i++) {
			low[i] = (int) Math.floor(i * floorSize / res + EPS);
		}
		return low;
	}

	private static int[] high(int count, double floorSize, double res, int cells) {
		int[] high = new int[count];
		for (int i = 0; i < count; i++) {
			high[i] = (int) Math.min(Math.ceil((i + 1) * floorSize / res - EPS), cells);
		}
		return high;
	}
}
