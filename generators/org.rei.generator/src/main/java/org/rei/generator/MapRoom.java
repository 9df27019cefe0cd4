/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;

import org.rei.context.Environment;
import org.rei.context.OccupancyLayout;
import org.rei.context.layout.MapFiles;
import org.rei.maps.CellRect;
import org.rei.maps.MapCache;
import org.rei.maps.MapException;
import org.rei.maps.OccupancyMap;

/**
 * A room from an occupancy map, as the generator needs it: the map (world frame = map frame, cell (0, 0)'s corner at
 * its origin), its obstacle rectangles (the walls {@code W_map_<col>_<row>}) and the copy of its files in the case
 * folder, so that a case folder is self-contained (docs/artifacts.md).
 */
record MapRoom(OccupancyLayout layout, OccupancyMap map) {

	/** File names of the copies in the case folder: {@code map.yaml} and {@code map.pgm} or {@code map.png}. */
	static final String YAML = "map.yaml";

	/** The map room of an environment, or {@code null} for another room. */
	static MapRoom of(Environment environment) throws GenerationException {
		if (!(environment.getOwnedLayout() instanceof OccupancyLayout layout)) {
			return null;
		}
		Path yaml = MapFiles.yamlOf(layout)
				.orElseThrow(() -> new GenerationException("the map " + layout.getMap() + " is not a file path"));
		try {
			return new MapRoom(layout, MapCache.get(yaml));
		} catch (MapException e) {
			throw new GenerationException("cannot use the map: " + e.getMessage(), e);
		}
	}

	/** The name of the image's copy. */
	String imageName() {
		return "map." + map.imageFormat();
	}

	/** The obstacle rectangles, in the order of the Python side's {@code merge_rectangles}. */
	List<CellRect> walls() {
		return map.obstacleRectangles(layout.isUnknownFree());
	}

	/** The wall of a rectangle, named after its bottom-left cell. */
	static String wallName(CellRect rect) {
		return "W_map_" + rect.col() + "_" + rect.row();
	}

	/** Copies the image byte for byte and writes the YAML naming the copy. */
	List<Path> copyInto(Path outputDir) throws GenerationException {
		Path yaml = outputDir.resolve(YAML);
		Path image = outputDir.resolve(imageName());
		try {
			Files.copy(map.image(), image, StandardCopyOption.REPLACE_EXISTING);
			Files.writeString(yaml, map.yamlNaming(imageName()), StandardCharsets.UTF_8);
		} catch (IOException e) {
			throw new GenerationException("cannot copy the map " + map.yaml() + " into " + outputDir + ": " + e, e);
		}
		return List.of(yaml, image);
	}

	/** A number with every digit the YAML gave (consumers compute cells from it), never an exponent. */
	private static String exact(double value) {
		String plain = java.math.BigDecimal.valueOf(value).toPlainString();
		return plain.contains(".") ? plain : plain + ".0";
	}

	/** world.json's {@code map} member (docs/artifacts.md). */
	String json() {
		return "{\"yaml\": \"" + YAML + "\", \"image\": \"" + imageName() + "\", \"resolution\": "
				+ exact(map.resolution()) + ", \"origin\": [" + exact(map.originX()) + ", " + exact(map.originY())
				+ ", 0.0], \"width\": " + map.width() + ", \"height\": "
				+ map.height() + ", \"unknownFree\": " + layout.isUnknownFree() + "}";
	}
}
