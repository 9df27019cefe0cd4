/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.catalogue.util;

import java.util.List;

import org.rei.catalogue.ObjectType;
import org.rei.catalogue.Shape;
import org.rei.catalogue.Vertex;

/**
 * A POLYGON type's footprint (docs/language.md#catalogues): what makes it usable (at least 3 vertices, an area,
 * no edge crossing or touching another) and where it stands: its bounding box centred on the object's place,
 * counter-clockwise, as world.json carries it.
 */
public final class Polygons {

	/** Below this area (m^2) a polygon has none. */
	public static final double MIN_AREA = 1e-9;

	private Polygons() {
	}

	/** True for a type whose footprint is its polygon. */
	public static boolean isPolygon(ObjectType type) {
		return type != null && type.getShape() == Shape.POLYGON;
	}

	/** The vertices as {@code [x, y]} rows, as written. */
	public static double[][] points(ObjectType type) {
		List<Vertex> vertices = type.getVertices();
		double[][] out = new double[vertices.size()][];
		for (int i = 0; i < out.length; i++) {
			out[i] = new double[] { vertices.get(i).getX(), vertices.get(i).getY() };
		}
		return out;
	}

	/** Twice the signed area: above 0 counter-clockwise. */
	public static double doubleArea(double[][] p) {
		double a = 0;
		for (int i = 0; i < p.length; i++) {
			double[] u = p[i];
			double[] v = p[(i + 1) % p.length];
			a += u[0] * v[1] - v[0] * u[1];
		}
		return a;
	}

	/** {@code [xmin, ymin, xmax, ymax]}. */
	public static double[] bounds(double[][] p) {
		double[] b = { Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
				Double.NEGATIVE_INFINITY };
		for (double[] q : p) {
			b[0] = Math.min(b[0], q[0]);
			b[1] = Math.min(b[1], q[1]);
			b[2] = Math.max(b[2], q[0]);
			b[3] = Math.max(b[3], q[1]);
		}
		return b;
	}

	/**
	 * The footprint as world.json carries it: the vertices less their bounding box's centre (so the object's
	 * pose, a floor centre, is that centre, as a box's), counter-clockwise (reversed when written clockwise).
	 */
	public static double[][] centred(ObjectType type) {
		double[][] p = points(type);
		double[] b = bounds(p);
		double cx = (b[0] + b[2]) / 2;
		double cy = (b[1] + b[3]) / 2;
		boolean reverse = doubleArea(p) < 0;
		double[][] out = new double[p.length][];
		for (int i = 0; i < p.length; i++) {
			double[] q = p[reverse ? (p.length - 1 - i + 1) % p.length : i];
			// to the picometre: 0.6 - 0.7 is -0.09999999999999998, where the text said 0.1 less than 0.7
			out[i] = new double[] { Math.round((q[0] - cx) * 1e12) / 1e12, Math.round((q[1] - cy) * 1e12) / 1e12 };
		}
		return out;
	}

	/**
	 * The first pair of edges that cross or touch (other than neighbours at their shared vertex), as the indices
	 * of their first vertices {@code [i, j]}, {@code i < j}; null for a simple polygon. Edge i runs from vertex i
	 * to vertex i + 1 (the last back to the first).
	 */
	public static int[] crossing(double[][] p) {
		int n = p.length;
		for (int i = 0; i < n; i++) {
			double[] a = p[i];
			double[] b = p[(i + 1) % n];
			if (a[0] == b[0] && a[1] == b[1]) {
				return new int[] { i, (i + 1) % n };
			}
		}
		for (int i = 0; i < n; i++) {
			for (int j = i + 1; j < n; j++) {
				double[] a = p[i];
				double[] b = p[(i + 1) % n];
				double[] c = p[j];
				double[] d = p[(j + 1) % n];
				boolean next = j == i + 1;
				boolean wrap = i == 0 && j == n - 1;
				if (next || wrap) {
					// neighbours share one vertex: they meet wrongly only when they fold back along one line
					double[] shared = next ? b : a;
					double[] u = next ? a : b;
					double[] w = next ? d : c;
					if (orientation(u, shared, w) == 0 && dot(u, shared, w) > 0) {
						return new int[] { i, j };
					}
					continue;
				}
				if (segmentsMeet(a, b, c, d)) {
					return new int[] { i, j };
				}
			}
		}
		return null;
	}

	/** True when every vertex lies on one line (or all are one point): the polygon has no area. */
	public static boolean collinear(double[][] p) {
		for (int k = 1; k < p.length; k++) {
			if (p[k][0] != p[0][0] || p[k][1] != p[0][1]) {
				for (double[] q : p) {
					if (orientation(p[0], p[k], q) != 0) {
						return false;
					}
				}
				return true;
			}
		}
		return true;
	}

	/** Whether {@code u - shared} and {@code w - shared} point the same way (a fold back). */
	private static double dot(double[] u, double[] shared, double[] w) {
		return (u[0] - shared[0]) * (w[0] - shared[0]) + (u[1] - shared[1]) * (w[1] - shared[1]);
	}

	private static int orientation(double[] a, double[] b, double[] c) {
		double v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
		double scale = Math.max(1e-300, Math.abs(b[0] - a[0]) + Math.abs(b[1] - a[1]) + Math.abs(c[0] - a[0])
				+ Math.abs(c[1] - a[1]));
		return Math.abs(v) <= 1e-12 * scale * scale ? 0 : (v > 0 ? 1 : -1);
	}

	private static boolean onSegment(double[] a, double[] b, double[] q) {
		return Math.min(a[0], b[0]) <= q[0] && q[0] <= Math.max(a[0], b[0]) && Math.min(a[1], b[1]) <= q[1]
				&& q[1] <= Math.max(a[1], b[1]);
	}

	private static boolean segmentsMeet(double[] a, double[] b, double[] c, double[] d) {
		int o1 = orientation(a, b, c);
		int o2 = orientation(a, b, d);
		int o3 = orientation(c, d, a);
		int o4 = orientation(c, d, b);
		if (o1 != o2 && o3 != o4) {
			return true;
		}
		return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) || (o3 == 0 && onSegment(c, d, a))
				|| (o4 == 0 && onSegment(c, d, b));
	}
}
