/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.geometry;

/**
 * A footprint in the body frame: an oriented rectangle (boxes, meshes by their bounding box, the robot) or a circle
 * (cylinders), as the catalogue says (thesis 6.1.3.1).
 */
public record Shape(Kind kind, double sizeX, double sizeY) {

	/** The two footprint primitives. */
	public enum Kind {
		RECTANGLE, CIRCLE
	}

	public Shape {
		if (!(sizeX > 0) || !(sizeY > 0)) {
			throw new IllegalArgumentException("footprint sizes must be positive, got " + sizeX + " x " + sizeY);
		}
	}

	/** A rectangle of {@code sizeX} by {@code sizeY} centred on the body origin. */
	public static Shape rectangle(double sizeX, double sizeY) {
		return new Shape(Kind.RECTANGLE, sizeX, sizeY);
	}

	/** A circle of the given diameter centred on the body origin. */
	public static Shape circle(double diameter) {
		return new Shape(Kind.CIRCLE, diameter, diameter);
	}

	/** Radius of the smallest circle around the body origin that holds the footprint at any yaw. */
	public double boundingRadius() {
		return kind == Kind.CIRCLE ? sizeX / 2 : Math.hypot(sizeX, sizeY) / 2;
	}

	/** Radius of the largest circle around the body origin inside the footprint. */
	public double inscribedRadius() {
		return Math.min(sizeX, sizeY) / 2;
	}

	public double radius() {
		return sizeX / 2;
	}
}
