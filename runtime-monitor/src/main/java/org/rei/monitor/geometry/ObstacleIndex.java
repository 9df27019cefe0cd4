/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.geometry;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.strtree.STRtree;

/**
 * Where the obstacles are, so that a step only looks at the robot's neighbourhood (the thesis's radius pre-filter,
 * 6.1.3.2). Static obstacles (walls, furniture: most of them, and they never move) sit in a JTS STRtree that is
 * built once; moving ones (humans, carts: few) are kept in a map and checked by envelope. An STRtree cannot be
 * changed after it is built, so a static obstacle that is ever re-placed makes the tree be rebuilt lazily.
 */
public final class ObstacleIndex {

	private final Map<String, Footprint> statics = new HashMap<>();
	private final Map<String, Footprint> moving = new HashMap<>();
	private STRtree tree;

	/** Adds or moves a static obstacle; a no-op when it is already there. */
	public void putStatic(Footprint footprint) {
		Footprint old = statics.put(footprint.name(), footprint);
		if (old != footprint) {
			moving.remove(footprint.name());
			tree = null;
		}
	}

	/** Adds or moves a moving obstacle. */
	public void putMoving(Footprint footprint) {
		if (statics.remove(footprint.name()) != null) {
			tree = null;
		}
		moving.put(footprint.name(), footprint);
	}

	/** Takes a moving obstacle out (it is not observed); its footprint, or null when it was not in. */
	public Footprint removeMoving(String name) {
		return moving.remove(name);
	}

	/** The footprint currently known for {@code name}, or null. */
	public Footprint get(String name) {
		Footprint f = moving.get(name);
		return f != null ? f : statics.get(name);
	}

	public boolean isStatic(String name) {
		return statics.containsKey(name);
	}

	public int size() {
		return statics.size() + moving.size();
	}

	/** Every obstacle whose envelope intersects {@code area}. */
	public void candidates(Envelope area, Consumer<Footprint> out) {
		if (tree == null) {
			tree = new STRtree();
			for (Footprint f : statics.values()) {
				tree.insert(f.envelope(), f);
			}
			tree.build();
		}
		tree.query(area, item -> out.accept((Footprint) item));
		for (Footprint f : moving.values()) {
			if (f.envelope().intersects(area)) {
				out.accept(f);
			}
		}
	}

	/** Convenience for tests: the candidates as a list. */
	public List<Footprint> candidates(Envelope area) {
		List<Footprint> out = new ArrayList<>();
		candidates(area, out::add);
		return out;
	}

	public Collection<Footprint> all() {
		List<Footprint> out = new ArrayList<>(statics.values());
		out.addAll(moving.values());
		return out;
	}
}
