/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.layout;

import org.rei.catalogue.ObjectType;
import org.rei.context.Direction;
import org.rei.context.Floor;
import org.rei.context.Wall;

/**
 * Where a wall stands: centred on the side of the first floor that names it, axis-aligned (yaw 0).
 *
 * @param wall the wall
 * @param floor the first floor (model order) that names the wall
 * @param side the side of {@code floor} the wall is on
 * @param type the wall's catalogue type, the default Wall type when the wall has none
 * @param x centre x in metres
 * @param y centre y in metres
 * @param z centre z in metres (half the height: walls stand on the floor surface z = 0)
 * @param sizeX extent along x
 * @param sizeY extent along y
 * @param sizeZ height
 */
public record WallPlacement(Wall wall, Floor floor, Direction side, ObjectType type, double x, double y, double z,
		double sizeX, double sizeY, double sizeZ) {
}
