/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import org.eclipse.xtext.validation.Check;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.context.OccupancyLayout;
import org.rei.dsl.derived.RoomDesugaring;
import org.rei.maps.FloorBlocks;
import org.rei.maps.MapBlocks;
import org.rei.maps.MapException;
import org.rei.maps.OccupancyMap;

/**
 * A room from an occupancy map: the map must be readable (every problem at the YAML line and column of the field,
 * or the image's property, on the map's string in the test case), its floor size must not cut it into more blocks
 * than {@link MapBlocks#MAX_BLOCKS} (on the floor size), and its free blocks must be floors enough and not too many.
 * References to blocks that are not free are reported by
 * {@link org.rei.dsl.scoping.ReiLinkingDiagnosticMessageProvider}.
 */
public class MapRoomValidator extends ReiCheckBase {

	@Check
	public void checkMap(OccupancyLayout layout) {
		OccupancyMap map;
		try {
			map = RoomDesugaring.mapOf(layout);
		} catch (MapException e) {
			error("Cannot use the map " + describe(layout, e), layout, ContextPackage.Literals.OCCUPANCY_LAYOUT__MAP,
					ReiIssueCodes.MAP_UNREADABLE);
			return;
		}
		if (!(layout.eContainer() instanceof Environment environment) || !(environment.getFloorSize() > 0)) {
			return; // RoomValidator reports the floor size
		}
		String size = RoomDesugaring.metres(environment.getFloorSize());
		double[] grid = MapBlocks.blockGrid(map, environment.getFloorSize());
		if (MapBlocks.tooManyBlocks(grid)) {
			// counted in doubles before any block is made: 0.0000001 m over 10 x 6 m is 6 * 10^15 blocks
			error("floorSize " + size + " m cuts the map " + layout.getMap() + " (" + map.width() + " x "
					+ map.height() + " cells of " + RoomDesugaring.metres(map.resolution()) + " m) into "
					+ MapBlocks.count(grid[0]) + " x " + MapBlocks.count(grid[1]) + " blocks: a room's map may be cut"
					+ " into at most " + MapBlocks.MAX_BLOCKS + " blocks (free or not); use a larger floorSize",
					environment, ContextPackage.Literals.ENVIRONMENT__FLOOR_SIZE, ReiIssueCodes.ROOM_TOO_LARGE);
			return;
		}
		FloorBlocks blocks = map.floorBlocks(environment.getFloorSize(), layout.isUnknownFree());
		if (blocks.freeCount() > RoomDesugaring.MAX_MAP_FLOORS) {
			error("The map " + layout.getMap() + " has " + blocks.freeCount() + " free blocks of " + size
					+ " m: a room may have at most " + RoomDesugaring.MAX_MAP_FLOORS
					+ " floors from a map; use a larger floorSize", layout,
					ContextPackage.Literals.OCCUPANCY_LAYOUT__MAP, ReiIssueCodes.ROOM_TOO_LARGE);
		} else if (blocks.freeCount() == 0) {
			error("The map " + layout.getMap() + " (" + map.width() + " x " + map.height() + " cells of "
					+ RoomDesugaring.metres(map.resolution()) + " m) has no free block of " + size
					+ " m, so no floor: every block overlaps an obstacle" + (layout.isUnknownFree() ? ""
							: " or unknown") + " cell, or the map is smaller than one block", layout,
					ContextPackage.Literals.OCCUPANCY_LAYOUT__MAP, ReiIssueCodes.EMPTY_LAYOUT);
		}
	}

	/** {@code YAML:LINE:COLUMN: FIELD: what}, the YAML named as the test case names it. */
	private static String describe(OccupancyLayout layout, MapException e) {
		return layout.getMap() + ":" + e.line() + ":" + e.column() + ": " + e.field() + ": " + e.detail();
	}
}
