/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.geometry;

import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;

/**
 * A shape placed at a planar pose: the JTS geometry (polygon of a rectangle or polygon, centre point of a circle) and its
 * envelope. Immutable; a moved body gets a new footprint.
 */
public final class Footprint {

	private static final GeometryFactory GEOMETRY = new GeometryFactory();

	private final String name;
	private final Shape shape;
	private final double x;
	private final double y;
	private final double yaw;
	private final Geometry geometry;
	private final Envelope envelope;

	private Footprint(String name, Shape shape, double x, double y, double yaw) {
		this.name = name;
		this.shape = shape;
		this.x = x;
		this.y = y;
		this.yaw = yaw;
		if (shape.kind() == Shape.Kind.CIRCLE) {
			// a circle stays exact: its distance is the centre's distance minus the radius (no polygonised buffer)
			double c = Math.cos(yaw);
			double s = Math.sin(yaw);
			double cx = x + c * shape.centreX() - s * shape.centreY();
			double cy = y + s * shape.centreX() + c * shape.centreY();
			geometry = GEOMETRY.createPoint(new Coordinate(cx, cy));
			double r = shape.radius();
			envelope = new Envelope(cx - r, cx + r, cy - r, cy + r);
		} else if (shape.kind() == Shape.Kind.POLYGON) {
			geometry = polygon(shape.points(), x, y, yaw);
			envelope = geometry.getEnvelopeInternal();
		} else {
			geometry = rectangle(shape.sizeX() / 2, shape.sizeY() / 2, x, y, yaw);
			envelope = geometry.getEnvelopeInternal();
		}
	}

	private static Geometry polygon(double[][] points, double x, double y, double yaw) {
		double c = Math.cos(yaw);
		double s = Math.sin(yaw);
		Coordinate[] ring = new Coordinate[points.length + 1];
		for (int i = 0; i < points.length; i++) {
			double u = points[i][0];
			double v = points[i][1];
			ring[i] = new Coordinate(x + c * u - s * v, y + s * u + c * v);
		}
		ring[points.length] = ring[0].copy();
		return GEOMETRY.createPolygon(ring);
	}

	/** A circle's centre in the world (a round robot's need not be its origin). */
	public double circleX() {
		return geometry.getCoordinate().x;
	}

	/** A circle's centre in the world. */
	public double circleY() {
		return geometry.getCoordinate().y;
	}

	/** The footprint of {@code shape} at {@code (x, y)} turned by {@code yaw} radians. */
	public static Footprint place(String name, Shape shape, double x, double y, double yaw) {
		return new Footprint(name, shape, x, y, yaw);
	}

	private static Geometry rectangle(double hx, double hy, double x, double y, double yaw) {
		double c = Math.cos(yaw);
		double s = Math.sin(yaw);
		Coordinate[] ring = new Coordinate[5];
		double[][] corners = { { hx, hy }, { -hx, hy }, { -hx, -hy }, { hx, -hy } };
		for (int i = 0; i < 4; i++) {
			double u = corners[i][0];
			double v = corners[i][1];
			ring[i] = new Coordinate(x + c * u - s * v, y + s * u + c * v);
		}
		ring[4] = ring[0].copy();
		return GEOMETRY.createPolygon(ring);
	}

	/** True when this footprint is still the one for the given pose (a resent static object need not move). */
	public boolean isAt(double px, double py, double pyaw) {
		return px == x && py == y && (pyaw == yaw || shape.kind() == Shape.Kind.CIRCLE);
	}

	public String name() {
		return name;
	}

	public Shape shape() {
		return shape;
	}

	public double x() {
		return x;
	}

	public double y() {
		return y;
	}

	public double yaw() {
		return yaw;
	}

	public Geometry geometry() {
		return geometry;
	}

	public Envelope envelope() {
		return envelope;
	}

	public boolean isCircle() {
		return shape.kind() == Shape.Kind.CIRCLE;
	}
}
