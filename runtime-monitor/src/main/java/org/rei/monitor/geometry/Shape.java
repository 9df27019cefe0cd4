/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.geometry;

/**
 * A footprint in the body frame: an oriented rectangle centred on the body origin (boxes, meshes by their bounding
 * box, a box robot), a circle (cylinders; a round robot's centred at {@code (centreX, centreY)}) or a polygon (a
 * robot read from its URDF description: its collision shapes' outline, convex, docs/robots.md; a POLYGON object of
 * the catalogue: a simple polygon, convex or not, whose distances JTS measures as they are), as the catalogue or
 * world.json says (thesis 6.1.3.1). {@code sizeX}, {@code sizeY} are a polygon's bounding box.
 */
public record Shape(Kind kind, double sizeX, double sizeY, double centreX, double centreY, double[][] points) {

	/** The footprint primitives. */
	public enum Kind {
		RECTANGLE, CIRCLE, POLYGON
	}

	public Shape {
		if (!(sizeX > 0) || !(sizeY > 0)) {
			throw new IllegalArgumentException("footprint sizes must be positive, got " + sizeX + " x " + sizeY);
		}
	}

	/** A rectangle of {@code sizeX} by {@code sizeY} centred on the body origin. */
	public static Shape rectangle(double sizeX, double sizeY) {
		return new Shape(Kind.RECTANGLE, sizeX, sizeY, 0, 0, null);
	}

	/** A circle of the given diameter centred on the body origin. */
	public static Shape circle(double diameter) {
		return new Shape(Kind.CIRCLE, diameter, diameter, 0, 0, null);
	}

	/** A circle of the given radius centred on {@code (x, y)} of the body frame. */
	public static Shape circle(double x, double y, double radius) {
		return new Shape(Kind.CIRCLE, 2 * radius, 2 * radius, x, y, null);
	}

	/** A polygon of body-frame {@code [x, y]} points, counter-clockwise (at least 3; a robot's is convex). */
	public static Shape polygon(double[][] points) {
		if (points.length < 3) {
			throw new IllegalArgumentException("a footprint polygon has at least 3 points, got " + points.length);
		}
		double xmin = Double.POSITIVE_INFINITY;
		double ymin = Double.POSITIVE_INFINITY;
		double xmax = Double.NEGATIVE_INFINITY;
		double ymax = Double.NEGATIVE_INFINITY;
		for (double[] p : points) {
			xmin = Math.min(xmin, p[0]);
			xmax = Math.max(xmax, p[0]);
			ymin = Math.min(ymin, p[1]);
			ymax = Math.max(ymax, p[1]);
		}
		return new Shape(Kind.POLYGON, xmax - xmin, ymax - ymin, 0, 0, points.clone());
	}

	/** Radius of the smallest circle around the body origin that holds the footprint at any yaw. */
	public double boundingRadius() {
		return switch (kind) {
		case CIRCLE -> Math.hypot(centreX, centreY) + sizeX / 2;
		case RECTANGLE -> Math.hypot(sizeX, sizeY) / 2;
		case POLYGON -> {
			double r = 0;
			for (double[] p : points) {
				r = Math.max(r, Math.hypot(p[0], p[1]));
			}
			yield r;
		}
		};
	}

	/** Radius of the largest circle around the body origin inside the footprint (0 when the origin is outside). */
	public double inscribedRadius() {
		return switch (kind) {
		case CIRCLE -> Math.max(0, sizeX / 2 - Math.hypot(centreX, centreY));
		case RECTANGLE -> Math.min(sizeX, sizeY) / 2;
		case POLYGON -> {
			double r = Double.POSITIVE_INFINITY;
			for (int i = 0; i < points.length; i++) {
				double[] a = points[i];
				double[] b = points[(i + 1) % points.length];
				double ex = b[0] - a[0];
				double ey = b[1] - a[1];
				// signed distance of the origin left of the counter-clockwise edge: negative outside
				r = Math.min(r, (ex * -a[1] - ey * -a[0]) / Math.hypot(ex, ey));
			}
			yield Math.max(0, r);
		}
		};
	}

	public double radius() {
		return sizeX / 2;
	}
}
