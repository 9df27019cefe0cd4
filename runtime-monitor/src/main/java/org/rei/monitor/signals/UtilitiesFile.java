/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.signals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Map;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * {@code --utilities-out FILE}: the utility each signal's pattern declares ({@code signal SIG_X utility -2},
 * docs/vepl.md) as one JSON object {@code {"SIG_X": -2.0, "SIG_Y": null}}, null for a signal declared without a
 * utility. The evaluator scores with it, so a user's own signal is worth what its pattern says.
 */
public final class UtilitiesFile {

	private static final ObjectMapper JSON = new ObjectMapper();

	private UtilitiesFile() {
	}

	/** The JSON text, keys in the order given (declaration order). */
	public static String json(Map<String, Double> utilities) {
		try {
			return JSON.writeValueAsString(utilities) + "\n";
		} catch (JsonProcessingException e) {
			throw new IllegalStateException(e); // a map of strings to doubles always serialises
		}
	}

	/** Writes {@code file} atomically: a reader never sees half of it. */
	public static void write(Path file, Map<String, Double> utilities) throws IOException {
		Path dir = file.toAbsolutePath().getParent();
		Path tmp = Files.createTempFile(dir, file.getFileName().toString(), ".tmp");
		try {
			Files.writeString(tmp, json(utilities), StandardCharsets.UTF_8);
			Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
		} finally {
			Files.deleteIfExists(tmp);
		}
	}
}
