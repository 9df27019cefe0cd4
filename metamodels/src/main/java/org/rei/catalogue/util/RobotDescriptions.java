/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.catalogue.util;

import java.nio.file.Path;

import org.eclipse.emf.common.util.URI;
import org.rei.catalogue.RobotType;

/** Where a robot type's URDF or xacro description is: one rule for the validator and the generator. */
public final class RobotDescriptions {

	private RobotDescriptions() {
	}

	/**
	 * The description's file, its path resolved against the catalogue file that declares the robot type (as a test
	 * case's imports are against the test case); {@code null} for a box robot or a catalogue not read from a file.
	 */
	public static Path file(RobotType robot) {
		String path = robot.getDescription();
		if (path == null) {
			return null;
		}
		Path given = Path.of(path);
		if (given.isAbsolute()) {
			return given.normalize();
		}
		URI uri = robot.eResource() == null ? null : robot.eResource().getURI();
		if (uri == null || !uri.isFile()) {
			return null;
		}
		return Path.of(uri.toFileString()).toAbsolutePath().getParent().resolve(given).normalize();
	}
}
