/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A loaded map: the grid Nav2's {@code map_server} would publish on {@code /map} ({@code -1} unknown, {@code 0} free,
 * {@code 100} occupied, {@code 1..99} in {@code scale} mode), row 0 at the bottom as in
 * {@code nav_msgs/OccupancyGrid.data}. Immutable; the obstacle rectangles and floor blocks derived from it are
 * computed once per argument and kept, since the editor asks for them on every keystroke.
 */
public final class OccupancyMap {

	public static final byte FREE = 0;
	public static final byte OCCUPIED = 100;
	public static final byte UNKNOWN = -1;

	/** The map_server modes, Nav2's default first. */
	public static final List<String> MODES = List.of("trinary", "scale", "raw");

	/**
	 * The most cells (image pixels) a map may have, checked from the image's header (PNG IHDR, PGM header) before
	 * anything is decoded: 50,000,000, e.g. 7,000 x 7,000 cells, 350 x 350 m at 0.05 m. A small file may declare
	 * a huge image (a PNG of 1.4 MB can hold 100,000 x 100,000 one-bit pixels); within the limit a map is read in
	 * memory proportional to its cells. The Python side's {@code rei.maps.MAX_CELLS} is the same number: both are
	 * copies of {@code maps.max_cells} in contract/vocabulary.json.
	 */
	public static final long MAX_CELLS = 50_000_000L;

	private final Path yaml;
	private final Path image;
	private final String yamlText;
	private final int imageValueStart;
	private final int imageValueEnd;
	private final double resolution;
	private final double originX;
	private final double originY;
	private final boolean negate;
	private final double occupiedThresh;
	private final double freeThresh;
	private final String mode;
	private final int width;
	private final int height;
	private final byte[] grid;
	private final Map<Boolean, List<CellRect>> rectangles = new ConcurrentHashMap<>();
	private final Map<String, FloorBlocks> blocks = new ConcurrentHashMap<>();

	OccupancyMap(Path yaml, Path image, String yamlText, int imageValueStart, int imageValueEnd, double resolution,
			double originX, double originY, boolean negate, double occupiedThresh, double freeThresh, String mode,
			int width, int height, byte[] grid) {
		this.yaml = yaml;
		this.image = image;
		this.yamlText = yamlText;
		this.imageValueStart = imageValueStart;
		this.imageValueEnd = imageValueEnd;
		this.resolution = resolution;
		this.originX = originX;
		this.originY = originY;
		this.negate = negate;
		this.occupiedThresh = occupiedThresh;
		this.freeThresh = freeThresh;
		this.mode = mode;
		this.width = width;
		this.height = height;
		this.grid = grid;
	}

	/** The YAML file. */
	public Path yaml() {
		return yaml;
	}

	/** The image file the YAML names. */
	public Path image() {
		return image;
	}

	/** The image's kind, also the extension of its copy: {@code pgm} or {@code png}. */
	public String imageFormat() {
		return MapImages.formatOf(image);
	}

	/**
	 * The YAML text as written, with the {@code image} field's value replaced by {@code imageName}: every other
	 * field and comment stays as the user wrote it.
	 */
	public String yamlNaming(String imageName) {
		return yamlText.substring(0, imageValueStart) + imageName + yamlText.substring(imageValueEnd);
	}

	/** Metres per cell. */
	public double resolution() {
		return resolution;
	}

	/** World x of the grid's bottom-left corner. */
	public double originX() {
		return originX;
	}

	/** World y of the grid's bottom-left corner. */
	public double originY() {
		return originY;
	}

	public boolean negate() {
		return negate;
	}

	public double occupiedThresh() {
		return occupiedThresh;
	}

	public double freeThresh() {
		return freeThresh;
	}

	/** {@code trinary}, {@code scale} or {@code raw}. */
	public String mode() {
		return mode;
	}

	/** Cells along x. */
	public int width() {
		return width;
	}

	/** Cells along y. */
	public int height() {
		return height;
	}

	/** The value of cell {@code (col, row)}, row 0 at the bottom. */
	public byte cell(int col, int row) {
		return grid[row * width + col];
	}

	/** The obstacle cells merged into rectangles, as {@link MapBlocks#mergeRectangles} gives them (kept). */
	public List<CellRect> obstacleRectangles(boolean unknownFree) {
		return rectangles.computeIfAbsent(unknownFree,
				u -> List.copyOf(MapBlocks.mergeRectangles(MapBlocks.obstacleMask(this, u), width, height)));
	}

	/** The floor blocks of {@code floorSize} metres, as {@link MapBlocks#floorBlocks} gives them (kept). */
	public FloorBlocks floorBlocks(double floorSize, boolean unknownFree) {
		return blocks.computeIfAbsent(floorSize + "/" + unknownFree,
				k -> MapBlocks.floorBlocks(this, floorSize, unknownFree));
	}

	/** A rectangle in world metres: {@code [centreX, centreY, sizeX, sizeY]}. */
	public double[] boxOf(CellRect rect) {
		return new double[] { originX + (rect.col() + rect.cols() / 2.0) * resolution,
				originY + (rect.row() + rect.rows() / 2.0) * resolution, rect.cols() * resolution,
				rect.rows() * resolution };
	}
}
