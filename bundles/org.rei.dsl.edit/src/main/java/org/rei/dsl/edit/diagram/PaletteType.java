/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.diagram;

/**
 * A catalogue type the room editor offers for new elements.
 *
 * @param category the role it plays, as a catalogue declares it: object, dynamic, human, robot, floor or wall
 * @param shape box, cylinder or polygon (its sizes the bounding box's)
 * @param sizeX metres along x
 * @param sizeY metres along y
 * @param colour as the catalogue writes it ({@code #RRGGBB}); a type that names none has the metamodel's grey
 */
public record PaletteType(String name, String category, String shape, double sizeX, double sizeY, String colour) {
}
