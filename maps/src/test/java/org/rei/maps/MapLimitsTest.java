/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The limits that keep a small file from taking the machine's memory: a map's cells ({@link OccupancyMap#MAX_CELLS},
 * checked from the image's header before anything is decoded, the Python side's message word for word), a large map
 * within them read in memory proportional to its cells, and the blocks a floor size may cut a map into
 * ({@link MapBlocks#MAX_BLOCKS}, counted without overflow before anything is allocated). Every image here is made by
 * the test: a header and a little compressed data, never a big file in the repository.
 */
class MapLimitsTest {

	private static final String YAML = """
			# a map whose image is written by the test
			image: big.IMAGE
			resolution: 0.05
			origin: [0.0, 0.0, 0.0]
			negate: 0
			occupied_thresh: 0.65
			free_thresh: 0.25
			""";

	@TempDir
	Path folder;

	private Path yaml(String extension) throws IOException {
		return Files.writeString(folder.resolve("big.yaml"), YAML.replace("IMAGE", extension));
	}

	/** A PNG chunk: length, type, data, CRC of type and data. */
	private static void chunk(ByteArrayOutputStream out, String type, byte[] data) {
		byte[] name = type.getBytes(StandardCharsets.US_ASCII);
		out.writeBytes(ByteBuffer.allocate(4).putInt(data.length).array());
		out.writeBytes(name);
		out.writeBytes(data);
		CRC32 crc = new CRC32();
		crc.update(name);
		crc.update(data);
		out.writeBytes(ByteBuffer.allocate(4).putInt((int) crc.getValue()).array());
	}

	/**
	 * A PNG that declares {@code width x height} pixels of {@code depth} bits (grey, not interlaced) and holds the
	 * compressed rows that {@code rows} gives (each with its filter byte), fewer than declared if it likes.
	 */
	private static byte[] png(long width, long height, int depth, byte[] rows) {
		ByteArrayOutputStream out = new ByteArrayOutputStream();
		out.writeBytes(new byte[] { (byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' });
		chunk(out, "IHDR", ByteBuffer.allocate(13).putInt((int) width).putInt((int) height).put((byte) depth)
				.put((byte) 0).put((byte) 0).put((byte) 0).put((byte) 0).array());
		Deflater deflater = new Deflater(9);
		deflater.setInput(rows);
		deflater.finish();
		ByteArrayOutputStream compressed = new ByteArrayOutputStream();
		byte[] buffer = new byte[1 << 16];
		while (!deflater.finished()) {
			compressed.write(buffer, 0, deflater.deflate(buffer));
		}
		deflater.end();
		chunk(out, "IDAT", compressed.toByteArray());
		chunk(out, "IEND", new byte[0]);
		return out.toByteArray();
	}

	private static String expectedDetail(Path image, String width, String height, String cells) {
		return image + ": " + width + " x " + height + " = " + cells + " cells: a map may have at most 50000000 cells"
				+ " (crop it, or save it at a coarser resolution)";
	}

	@Test
	void aPngDeclaringMoreCellsThanAMapMayHaveIsRefusedFromItsHeader() throws Exception {
		// 100,000 x 100,000 one-bit pixels (5 x 5 km at 0.05 m) announced by IHDR; three rows of data follow
		byte[] threeRows = new byte[3 * (1 + 100_000 / 8)];
		Path image = Files.write(folder.resolve("big.png"), png(100_000, 100_000, 1, threeRows));
		Path yaml = yaml("png");
		long start = System.nanoTime();
		MapException refused = assertThrows(MapException.class, () -> MapReader.read(yaml));
		assertEquals(List.of(2, 8, "image", image), List.of(refused.line(), refused.column(), refused.field(),
				refused.image()));
		assertEquals(expectedDetail(image, "100000", "100000", "10000000000"), refused.detail());
		assertTrue(System.nanoTime() - start < 2e9, "refused from the header, not after decoding");
	}

	@Test
	void aPgmDeclaringMoreCellsThanAMapMayHaveIsRefusedFromItsHeader() throws Exception {
		Path image = folder.resolve("big.pgm");
		Files.write(image, "P5\n# 5 x 5 km\n100000 100000\n255\n\u00fe\u00fe\u00fe".getBytes(StandardCharsets.ISO_8859_1));
		Path yaml = yaml("pgm");
		MapException refused = assertThrows(MapException.class, () -> MapReader.read(yaml));
		assertEquals(List.of(2, 8, "image"), List.of(refused.line(), refused.column(), refused.field()));
		assertEquals(expectedDetail(image, "100000", "100000", "10000000000"), refused.detail());

		// sizes beyond any Java integer are read as Python's int() reads them, and refused the same way
		Files.write(image, "P2\n123456789012345678901 2\n255\n0 0\n".getBytes(StandardCharsets.US_ASCII));
		MapException huge = assertThrows(MapException.class, () -> MapReader.read(yaml));
		assertEquals(expectedDetail(image, "123456789012345678901", "2", "246913578024691357802"), huge.detail());
	}

	/** Bytes the current thread allocated while {@code read} ran. */
	private static long allocatedBy(ThrowingRunnable read) throws Exception {
		com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory
				.getThreadMXBean();
		long before = threads.getCurrentThreadAllocatedBytes();
		read.run();
		return threads.getCurrentThreadAllocatedBytes() - before;
	}

	interface ThrowingRunnable {
		void run() throws Exception;
	}

	/** 4,000 x 4,000 cells, free but for the top row's wall and the left column's. */
	private static final int SIDE = 4_000;

	private static void checkWalls(OccupancyMap map) {
		assertEquals(List.of(SIDE, SIDE), List.of(map.width(), map.height()));
		assertEquals(List.of(OccupancyMap.OCCUPIED, OccupancyMap.OCCUPIED, OccupancyMap.FREE, OccupancyMap.OCCUPIED),
				List.of(map.cell(5, SIDE - 1), map.cell(0, 7), map.cell(SIDE - 1, 0), map.cell(0, 0)));
	}

	@Test
	void aLargePngWithinTheLimitIsReadInMemoryProportionalToItsCells() throws Exception {
		byte[] rows = new byte[SIDE * (SIDE + 1)];
		for (int row = 0; row < SIDE; row++) {
			int at = row * (SIDE + 1); // filter byte 0, then the row
			Arrays.fill(rows, at + 1, at + SIDE + 1, (byte) (row == 0 ? 0 : 254));
			rows[at + 1] = 0;
		}
		Files.write(folder.resolve("big.png"), png(SIDE, SIDE, 8, rows));
		Path yaml = yaml("png");
		OccupancyMap[] map = new OccupancyMap[1];
		long bytes = allocatedBy(() -> map[0] = MapReader.read(yaml));
		checkWalls(map[0]);
		// the decoded raster and the grid, a byte per cell each: not a double per cell and channel
		assertTrue(bytes < 3L * SIDE * SIDE, "allocated " + bytes + " bytes for " + SIDE * SIDE + " cells");
	}

	@Test
	void aLargePgmWithinTheLimitIsReadInMemoryProportionalToItsCells() throws Exception {
		byte[] header = ("P5\n" + SIDE + " " + SIDE + "\n255\n").getBytes(StandardCharsets.US_ASCII);
		byte[] image = Arrays.copyOf(header, header.length + SIDE * SIDE);
		Arrays.fill(image, header.length + SIDE, image.length, (byte) 254); // the first (top) row stays 0
		for (int row = 0; row < SIDE; row++) {
			image[header.length + row * SIDE] = 0;
		}
		Files.write(folder.resolve("big.pgm"), image);
		Path yaml = yaml("pgm");
		OccupancyMap[] map = new OccupancyMap[1];
		long bytes = allocatedBy(() -> map[0] = MapReader.read(yaml));
		checkWalls(map[0]);
		// the grid, a byte per cell, and a row at a time: not the whole file and a double per cell
		assertTrue(bytes < 1.5 * SIDE * SIDE, "allocated " + bytes + " bytes for " + SIDE * SIDE + " cells");
	}

	@Test
	void aFloorSizeThatCutsTheMapIntoTooManyBlocksIsRefusedBeforeAnythingIsAllocated() throws Exception {
		byte[] header = "P5\n200 120\n255\n".getBytes(StandardCharsets.US_ASCII);
		byte[] image = Arrays.copyOf(header, header.length + 200 * 120);
		Arrays.fill(image, header.length, image.length, (byte) 254);
		Files.write(folder.resolve("big.pgm"), image);
		OccupancyMap map = MapReader.read(yaml("pgm")); // 10 x 6 m, as examples/maps/two_rooms

		assertArrayEquals(new double[] { 100_000_000, 60_000_000 }, MapBlocks.blockGrid(map, 0.0000001));
		assertArrayEquals(new double[] { 1e301, 6e300 }, MapBlocks.blockGrid(map, 1e-300), 1e287);
		IllegalArgumentException tiny = assertThrows(IllegalArgumentException.class,
				() -> map.floorBlocks(0.0000001, false));
		assertEquals("floor size 1e-07 m cuts the map's 200 x 120 cells of 0.05 m into 100000000 x 60000000 blocks: "
				+ "at most 4000000 (free or not); use a larger floor size", tiny.getMessage());
		IllegalArgumentException tinier = assertThrows(IllegalArgumentException.class,
				() -> map.floorBlocks(1e-300, false));
		assertTrue(tinier.getMessage().contains(" into 1e+301 x 6e+300 blocks"), tinier.getMessage());

		// at the limit: 2,000 x 1,200 blocks of 5 mm are 2,400,000, allowed
		FloorBlocks fine = map.floorBlocks(0.005, false);
		assertEquals(List.of(2000, 1200, 2_400_000), List.of(fine.columns(), fine.rows(), fine.freeCount()));
		assertTrue(MapBlocks.tooManyBlocks(MapBlocks.blockGrid(map, 0.0029)), "3448 x 2068 blocks: over");
	}
}
