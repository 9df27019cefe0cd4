/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The reader's own contract: positions of YAML problems, PGM details, the copy's YAML, the cache. That its cells,
 * floors and rectangles equal the Python side's for every mode and image format is tests/maps/test_map_room_parity.py.
 */
class MapReaderTest {

	private static final String YAML = """
			# a 4 x 3 map
			image: room.pgm
			resolution: 0.5
			origin: [-1.0, 2.0, 0.0]
			negate: 0
			occupied_thresh: 0.65
			free_thresh: 0.25
			""";

	/** Top row occupied, a free middle row with an unknown cell, bottom row free. */
	private static final String PGM = "P2\n# made by hand\n4 3\n255\n0 0 0 0\n254 205 128 254\n254 254 254 254\n";

	@TempDir
	Path folder;

	private Path write(String yaml, String image) throws IOException {
		Files.writeString(folder.resolve("room.pgm"), image, StandardCharsets.ISO_8859_1);
		return Files.writeString(folder.resolve("room.yaml"), yaml);
	}

	private MapException problem(String yaml, String image) throws IOException {
		Path file = write(yaml, image);
		return assertThrows(MapException.class, () -> MapReader.read(file));
	}

	@Test
	void readsTheGridBottomRowFirst() throws Exception {
		OccupancyMap map = MapReader.read(write(YAML, PGM));
		assertEquals(List.of(4, 3, 0.5, -1.0, 2.0, "trinary"), List.of(map.width(), map.height(), map.resolution(),
				map.originX(), map.originY(), map.mode()));
		byte[] bottom = { map.cell(0, 0), map.cell(1, 0), map.cell(2, 0), map.cell(3, 0) };
		byte[] middle = { map.cell(0, 1), map.cell(1, 1), map.cell(2, 1), map.cell(3, 1) };
		byte[] top = { map.cell(0, 2), map.cell(1, 2), map.cell(2, 2), map.cell(3, 2) };
		assertArrayEquals(new byte[] { 0, 0, 0, 0 }, bottom);
		assertArrayEquals(new byte[] { 0, 0, -1, 0 }, middle, "205 is free below free_thresh 0.25; 128 unknown");
		assertArrayEquals(new byte[] { 100, 100, 100, 100 }, top);
		assertEquals(List.of(new CellRect(2, 1, 1, 1), new CellRect(0, 2, 4, 1)), map.obstacleRectangles(false));
		assertEquals(List.of(new CellRect(0, 2, 4, 1)), map.obstacleRectangles(true));
		assertArrayEquals(new double[] { 0.0, 3.25, 2.0, 0.5 }, map.boxOf(new CellRect(0, 2, 4, 1)));
	}

	@Test
	void theCopysYamlKeepsEverythingButTheImageName() throws Exception {
		OccupancyMap map = MapReader.read(write(YAML, PGM));
		assertEquals(YAML.replace("image: room.pgm", "image: map.pgm"), map.yamlNaming("map.pgm"));
		// a character beyond 16 bits before the field (YAML marks count code points), a quoted name and a comment
		String quoted = "# plan of the \uD83C\uDFED hall\n"
				+ YAML.replace("image: room.pgm", "image: \"room.pgm\"  # the scan");
		assertEquals(quoted.replace("\"room.pgm\"", "map.pgm"),
				MapReader.read(write(quoted, PGM)).yamlNaming("map.pgm"));
		assertEquals("pgm", map.imageFormat());
	}

	@Test
	void blocksOverlappingPartCellsCountThemAll() throws Exception {
		// 0.75 m blocks over 0.5 m cells: block 0 is cells 0..1, block 1 cells 1..2 (it overlaps both halves)
		FloorBlocks blocks = MapReader.read(write(YAML, PGM)).floorBlocks(0.75, false);
		assertEquals(List.of(2, 2), List.of(blocks.columns(), blocks.rows()));
		assertEquals(List.of(true, false, false, false), List.of(blocks.isFree(0, 0), blocks.isFree(1, 0),
				blocks.isFree(0, 1), blocks.isFree(1, 1)));
		assertEquals(List.of(1, 4), List.of(blocks.obstacleCells(1, 0), blocks.cells(1, 0)));
	}

	@Test
	void problemsAreAtTheFieldsLineAndColumn() throws Exception {
		MapException missing = problem(YAML.replace("negate: 0\n", ""), PGM);
		assertEquals(List.of(2, 1, "negate", "missing (map_server requires it)"),
				List.of(missing.line(), missing.column(), missing.field(), missing.detail()));
		MapException wrong = problem(YAML.replace("resolution: 0.5", "resolution: [1]"), PGM);
		assertEquals("room.yaml:3:13: resolution: expected a number, got [1]",
				wrong.getMessage().substring(wrong.getMessage().lastIndexOf('/') + 1));
		MapException order = problem(YAML.replace("free_thresh: 0.25", "free_thresh: 0.7"), PGM);
		assertEquals(List.of(7, 14, "free_thresh", "0.7 must be below occupied_thresh 0.65"),
				List.of(order.line(), order.column(), order.field(), order.detail()));
		MapException twice = problem(YAML + "negate: 1\n", PGM);
		assertEquals(List.of(8, 1, "file", "'negate' is given twice"),
				List.of(twice.line(), twice.column(), twice.field(), twice.detail()));
		MapException syntax = problem("image: [room.pgm\n", PGM);
		assertEquals(List.of("file", 2), List.of(syntax.field(), syntax.line()));
		MapException depth = problem(YAML, "P5\n4 3\n70000\n");
		assertEquals(List.of(2, 8, "image"), List.of(depth.line(), depth.column(), depth.field()));
		assertEquals(folder.resolve("room.pgm") + ": PGM maxval 70000: expected 1..65535 (8 or 16 bits per sample)",
				depth.detail());
		assertEquals(folder.resolve("room.pgm"), depth.image());
	}

	@Test
	void sixteenBitPgmIsBigEndian() throws Exception {
		byte[] image = new byte[] { 'P', '5', '\n', '2', ' ', '1', '\n', '6', '5', '5', '3', '5', '\n', (byte) 0xff,
				(byte) 0xff, 0x00, 0x01 };
		write(YAML, "");
		Files.write(folder.resolve("room.pgm"), image);
		OccupancyMap map = MapReader.read(folder.resolve("room.yaml"));
		assertEquals(List.of((byte) 0, (byte) 100), List.of(map.cell(0, 0), map.cell(1, 0)));
	}

	@Test
	void theCacheReadsAMapOncePerVersionOfItsFiles() throws Exception {
		Path yaml = write(YAML, PGM);
		OccupancyMap first = MapCache.get(yaml);
		assertSame(first, MapCache.get(yaml));
		Path image = folder.resolve("room.pgm");
		Files.setLastModifiedTime(image, FileTime.fromMillis(Files.getLastModifiedTime(image).toMillis() + 5000));
		assertNotSame(first, MapCache.get(yaml));

		Files.writeString(image, "P2\n4 3\n255\n0\n");
		Files.setLastModifiedTime(image, FileTime.fromMillis(Files.getLastModifiedTime(image).toMillis() + 9000));
		MapException broken = assertThrows(MapException.class, () -> MapCache.get(yaml));
		assertSame(broken, assertThrows(MapException.class, () -> MapCache.get(yaml)), "a broken map is not re-read");
		Files.writeString(image, PGM, StandardCharsets.ISO_8859_1);
		Files.setLastModifiedTime(image, FileTime.fromMillis(Files.getLastModifiedTime(image).toMillis() + 13000));
		assertEquals(4, MapCache.get(yaml).width(), "a repaired image is read again");
	}

	@Test
	void numbersAreWrittenAsPythonsFormatG() {
		assertEquals(List.of("0.5", "0", "1e-05", "1.23457e+06", "0.65", "-2", "123457"),
				List.of(MapReader.g(0.5), MapReader.g(0.0), MapReader.g(0.00001), MapReader.g(1234567),
						MapReader.g(0.65), MapReader.g(-2), MapReader.g(123456.7)));
	}
}
