/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.layout;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.rei.context.Floor;
import org.rei.context.OccupancyLayout;

/** Where an occupancy room's map is, and which block of it a floor is. */
public final class MapFiles {

	private static final Pattern FLOOR_NAME = Pattern.compile("F_(\\d{1,9})_(\\d{1,9})");

	private MapFiles() {
	}

	/**
	 * The map's YAML file: the path as written when absolute, else relative to the folder of the file the room is
	 * written in (the working directory for a room that is in no file).
	 *
	 * @return empty when the text is no path
	 */
	public static Optional<Path> yamlOf(OccupancyLayout layout) {
		if (layout.getMap() == null) {
			return Optional.empty();
		}
		try {
			Path named = Path.of(layout.getMap());
			return Optional.of(named.isAbsolute() ? named : folderOf(layout.eResource()).resolve(named));
		} catch (InvalidPathException e) {
			return Optional.empty();
		}
	}

	private static Path folderOf(Resource resource) {
		URI uri = resource == null ? null : resource.getURI();
		if (uri != null && uri.isFile() && uri.toFileString() != null) {
			Path parent = Path.of(uri.toFileString()).toAbsolutePath().getParent();
			if (parent != null) {
				return parent;
			}
		}
		return Path.of("").toAbsolutePath();
	}

	/** The block {@code (x, y)} of a floor named {@code F_x_y}; empty for another name. */
	public static Optional<Cell> blockOf(Floor floor) {
		return blockOf(floor.getName());
	}

	/** The block {@code (x, y)} a name {@code F_x_y} stands for; empty for another name. */
	public static Optional<Cell> blockOf(String name) {
		Matcher m = name == null ? null : FLOOR_NAME.matcher(name);
		if (m == null || !m.matches()) {
			return Optional.empty();
		}
		return Optional.of(new Cell(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2))));
	}
}
