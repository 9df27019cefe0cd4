/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.replay;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.msgpack.core.MessagePack;
import org.msgpack.core.MessageUnpacker;

/**
 * A recorded stream ({@code OUT/streams/<name>.msgpack}, docs/protocol.md): the msgpack encodings of the messages,
 * concatenated. Read whole into memory and cut into messages without decoding them, so the replayed pipeline
 * decodes each message exactly as the live one does.
 */
public final class Recording {

	private final byte[] data;
	private final int[] offsets;
	private final boolean truncated;

	private Recording(byte[] data, int[] offsets, boolean truncated) {
		this.data = data;
		this.offsets = offsets;
		this.truncated = truncated;
	}

	public static Recording read(Path file) throws IOException {
		return of(Files.readAllBytes(file));
	}

	/** Cuts {@code data} into messages; a truncated last message (a crashed writer) is dropped and flagged. */
	public static Recording of(byte[] data) {
		List<Integer> bounds = new ArrayList<>();
		bounds.add(0);
		boolean truncated = false;
		try (MessageUnpacker in = MessagePack.newDefaultUnpacker(data)) {
			while (in.hasNext()) {
				in.skipValue();
				bounds.add((int) in.getTotalReadBytes());
			}
		} catch (IOException | RuntimeException e) {
			truncated = true;
		}
		return new Recording(data, bounds.stream().mapToInt(Integer::intValue).toArray(), truncated);
	}

	public int size() {
		return offsets.length - 1;
	}

	public byte[] data() {
		return data;
	}

	public int offset(int i) {
		return offsets[i];
	}

	public int length(int i) {
		return offsets[i + 1] - offsets[i];
	}

	public byte[] message(int i) {
		return java.util.Arrays.copyOfRange(data, offsets[i], offsets[i + 1]);
	}

	public boolean truncated() {
		return truncated;
	}
}
