/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.testing.util.ParseHelper;
import org.eclipse.xtext.testing.validation.ValidationTestHelper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.rei.context.BuildingBlock;
import org.rei.context.ContextPackage;
import org.rei.context.Floor;
import org.rei.context.OccupancyLayout;
import org.rei.context.TestCase;
import org.rei.dsl.derived.RoomDesugaring;
import org.rei.dsl.validation.ReiIssueCodes;
import org.rei.maps.MapCache;

import com.google.inject.Inject;

/**
 * Rooms from an occupancy map (src/test/resources/maps/small.pgm: 12 x 8 cells of 0.1 m, walled, a pillar cell and
 * two unknown cells): floors on the free blocks only, open sides, and the map read once per version of its files.
 */
@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class MapRoomTest {

	private static final Path SMALL = Path.of("src/test/resources/maps/small.yaml").toAbsolutePath();

	@Inject
	private ParseHelper<TestCase> parser;

	@Inject
	private ValidationTestHelper validation;

	private TestCase room(Path yaml, String flags) throws Exception {
		return parser.parse("testcase T {\n  room R occupancy \"" + yaml + "\"" + flags + " floorSize 0.2 {\n"
				+ "    object crate : Box on F_4_2\n    robot r : Waffle on F_2_1\n  }\n"
				+ "  mission M { goto F_4_1 goto F_2_2 }\n}\n");
	}

	@Test
	void floorsAreTheFreeBlocksWithOpenSidesAndNoWalls() throws Exception {
		TestCase testCase = room(SMALL, "");
		validation.assertNoIssues(testCase);
		assertEquals(Set.of("F_2_1", "F_3_1", "F_4_1", "F_1_2", "F_2_2", "F_4_2"), names(testCase));
		Floor f21 = floor(testCase, "F_2_1");
		assertSame(floor(testCase, "F_3_1"), f21.getRight());
		assertSame(floor(testCase, "F_2_2"), f21.getTop());
		assertNull(f21.getLeft(), "F_1_1 holds the pillar cell: an open side, no wall");
		assertNull(f21.getBottom(), "the map's bottom wall: an open side");
		assertTrue(testCase.getOwnedEnvironment().getOwnedBlocks().stream().allMatch(b -> b instanceof Floor));
	}

	@Test
	void unknownFreeMakesUnknownCellsFloor() throws Exception {
		TestCase testCase = room(SMALL, " unknownFree");
		validation.assertNoIssues(testCase);
		assertTrue(((OccupancyLayout) testCase.getOwnedEnvironment().getOwnedLayout()).isUnknownFree());
		assertEquals(Set.of("F_2_1", "F_3_1", "F_4_1", "F_1_2", "F_2_2", "F_3_2", "F_4_2"), names(testCase));
	}

	@Test
	void theMapIsReadOncePerVersionOfItsFiles(@TempDir Path folder) throws Exception {
		Path yaml = folder.resolve("small.yaml");
		Path image = folder.resolve("small.pgm");
		Files.copy(SMALL, yaml);
		Files.copy(SMALL.resolveSibling("small.pgm"), image);
		var first = MapCache.get(yaml);
		assertSame(first, RoomDesugaring.mapOf(layout(room(yaml, ""))), "revalidation reads no file");
		Files.setLastModifiedTime(image, FileTime.fromMillis(Files.getLastModifiedTime(image).toMillis() + 2000));
		assertNotSame(first, MapCache.get(yaml), "a changed image is read again");
	}

	@Test
	void aMapOfMoreFreeBlocksThanTheLimitAsksForLargerFloors(@TempDir Path folder) throws Exception {
		// 501 x 501 free cells of 0.1 m: 251,001 free blocks of 0.1 m, 2,500 of 1 m
		int side = 501;
		byte[] header = ("P5\n" + side + " " + side + "\n255\n").getBytes(java.nio.charset.StandardCharsets.US_ASCII);
		byte[] image = java.util.Arrays.copyOf(header, header.length + side * side);
		java.util.Arrays.fill(image, header.length, image.length, (byte) 254);
		Files.write(folder.resolve("hall.pgm"), image);
		Path yaml = Files.writeString(folder.resolve("hall.yaml"), "image: hall.pgm\nresolution: 0.1\n"
				+ "origin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.25\n");
		String text = "testcase T {\n  room R occupancy \"" + yaml + "\" floorSize SIZE {\n"
				+ "    robot r : Waffle on F_0_0\n  }\n  mission M { goto F_1_0 goto F_2_0 }\n}\n";
		TestCase tooMany = parser.parse(text.replace("SIZE", "0.1"));
		validation.assertError(tooMany, ContextPackage.Literals.OCCUPANCY_LAYOUT, ReiIssueCodes.ROOM_TOO_LARGE,
				"has 251001 free blocks of 0.1 m: a room may have at most 250000 floors from a map; use a larger "
						+ "floorSize");
		assertEquals(1, validation.validate(tooMany).size(), "no error for each floor it names");
		TestCase fine = parser.parse(text.replace("SIZE", "1.0"));
		validation.assertNoErrors(fine);
		assertEquals(2_500, fine.getOwnedEnvironment().getOwnedBlocks().size());
	}

	private static OccupancyLayout layout(TestCase testCase) {
		return (OccupancyLayout) testCase.getOwnedEnvironment().getOwnedLayout();
	}

	private static Set<String> names(TestCase testCase) {
		Set<String> names = new TreeSet<>();
		for (BuildingBlock block : testCase.getOwnedEnvironment().getOwnedBlocks()) {
			names.add(block.getName());
		}
		return names;
	}

	private static Floor floor(TestCase testCase, String name) {
		return (Floor) testCase.getOwnedEnvironment().getOwnedBlocks().stream().filter(b -> name.equals(b.getName()))
				.findFirst().orElseThrow();
	}
}
