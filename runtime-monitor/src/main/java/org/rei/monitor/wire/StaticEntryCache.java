/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wire;

import java.util.Arrays;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Lets the decoder skip the static obstacles that every full frame repeats unchanged, without decoding them.
 *
 * <p>
 * For each static obstacle of world.json the cache keeps the exact msgpack bytes of the last {@code objects} entry
 * that was decoded <em>and applied</em> for it, and where in the array it stood. When a later message has the same
 * bytes at an array position, the entry is skipped: msgpack is prefix-free, so equal bytes are the same complete
 * value (the name is part of them), and applying a value the object already has changes nothing. Only bytes are
 * compared; nothing is allocated for a skipped entry.
 *
 * <p>
 * Invariant: a kept entry's value is the object's current state. It is kept only after the message that carried
 * it was applied ({@link #applied}); an object changed by any message the cache did not decode, or by a message
 * that failed half-way ({@link #failed}), loses its entry, so its next full-frame entry is decoded and applied
 * again. Moving objects (humans, carts) are never kept: they may move between full frames and come back. Within
 * one message, an entry of an object that an earlier entry of the same message changed is never skipped.
 *
 * <p>
 * Not thread-safe: owned by one monitor, used between decoding a message and applying it.
 */
public final class StaticEntryCache {

	private static final class Slot {
		int position = -1;
		byte[] bytes;
		long touched = -1; // message stamp in which an entry of this object was decoded
	}

	private final Map<String, Slot> slots = new HashMap<>();
	private Slot[] byPosition = new Slot[16];
	private long stamp;
	private long skipped;
	// the entries decoded from the last message, in the order of its objects list
	private StateMessage pendingMessage;
	private byte[] pendingData;
	private int pendingCount;
	private int[] pendingPosition = new int[64];
	private int[] pendingStart = new int[64];
	private int[] pendingLength = new int[64];
	private Slot[] pendingSlot = new Slot[64];

	/** @param staticNames the obstacles that never move on their own (world.json walls and static furniture) */
	public StaticEntryCache(Collection<String> staticNames) {
		for (String name : staticNames) {
			slots.put(name, new Slot());
		}
	}

	/** Entries skipped so far (for tests and the benchmark). */
	public long skipped() {
		return skipped;
	}

	void begin(byte[] data) {
		stamp++;
		pendingMessage = null;
		pendingData = data;
		pendingCount = 0;
	}

	/**
	 * The length of the entry expected at array position {@code index} if {@code data[pos, limit)} starts with its
	 * kept bytes, else 0.
	 */
	int unchanged(int index, byte[] data, int pos, int limit) {
		if (index >= byPosition.length) {
			return 0;
		}
		Slot s = byPosition[index];
		if (s == null || s.bytes == null || s.touched == stamp) {
			return 0;
		}
		int n = s.bytes.length;
		if (limit - pos < n || !Arrays.equals(data, pos, pos + n, s.bytes, 0, n)) {
			return 0;
		}
		skipped++;
		return n;
	}

	/** An entry decoded normally at array position {@code index} from {@code data[start, start + length)}. */
	void decoded(int index, int start, int length, String name) {
		if (pendingCount == pendingPosition.length) {
			int n = pendingCount * 2;
			pendingPosition = Arrays.copyOf(pendingPosition, n);
			pendingStart = Arrays.copyOf(pendingStart, n);
			pendingLength = Arrays.copyOf(pendingLength, n);
			pendingSlot = Arrays.copyOf(pendingSlot, n);
		}
		Slot s = slots.get(name);
		if (s != null) {
			s.touched = stamp;
		}
		pendingPosition[pendingCount] = index;
		pendingStart[pendingCount] = start;
		pendingLength[pendingCount] = length;
		pendingSlot[pendingCount] = s;
		pendingCount++;
	}

	void end(StateMessage m) {
		pendingMessage = m;
	}

	/** {@code m} was applied completely: its decoded static entries become the reference for later frames. */
	public void applied(StateMessage m) {
		List<ObjectState> objects = m.objects();
		if (m != pendingMessage || pendingCount != objects.size()) {
			forget(objects); // not decoded here: what changed is unknown as bytes
			return;
		}
		for (int k = 0; k < pendingCount; k++) {
			Slot s = pendingSlot[k];
			if (s == null) {
				continue;
			}
			int position = pendingPosition[k];
			s.bytes = Arrays.copyOfRange(pendingData, pendingStart[k], pendingStart[k] + pendingLength[k]);
			if (s.position != position) {
				if (s.position >= 0 && byPosition[s.position] == s) {
					byPosition[s.position] = null;
				}
				if (position >= byPosition.length) {
					byPosition = Arrays.copyOf(byPosition, Math.max(position + 1, byPosition.length * 2));
				}
				byPosition[position] = s;
				s.position = position;
			}
		}
		release();
	}

	/** Applying {@code m} failed part-way: the objects it names may be in any state, so their entries go. */
	public void failed(StateMessage m) {
		forget(m.objects());
		release();
	}

	private void forget(List<ObjectState> objects) {
		for (ObjectState o : objects) {
			Slot s = slots.get(o.name());
			if (s != null) {
				s.bytes = null;
			}
		}
	}

	private void release() {
		pendingMessage = null;
		pendingData = null;
		pendingCount = 0;
	}
}
