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
import java.util.LinkedHashMap;
import java.util.Map;

import org.rei.vepl.compiler.CompiledRules;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * {@code --utilities-out FILE}: what each signal's pattern declares (docs/vepl.md), as one JSON object with a member
 * per signal in declaration order: {@code {"SIG_X": {"utility": -2.0, "transition": {"source": "GEOM", "from":
 * "FAR", "to": "CLOSE"}}, "SIG_Y": {"utility": null}}} - a null utility for a signal declared without one, a
 * transition only for a signal declared with one. The evaluator scores with the utilities and judges the
 * requirements on zones from the transitions, so a user's own signal counts as its pattern says.
 */
public final class UtilitiesFile {

	private static final ObjectMapper JSON = new ObjectMapper();

	private UtilitiesFile() {
	}

	/** The JSON text, keys in the order given (declaration order). */
	public static String json(Map<String, Double> utilities, Map<String, CompiledRules.Transition> transitions) {
		Map<String, Object> out = new LinkedHashMap<>();
		utilities.forEach((signal, utility) -> {
			Map<String, Object> declared = new LinkedHashMap<>();
			declared.put("utility", utility);
			CompiledRules.Transition t = transitions.get(signal);
			if (t != null) {
				Map<String, Object> transition = new LinkedHashMap<>();
				transition.put("source", t.source());
				transition.put("from", t.from());
				transition.put("to", t.to());
				if (t.perObject()) {
					transition.put("per_object", true);
				}
				declared.put("transition", transition);
			}
			out.put(signal, declared);
		});
		try {
			return JSON.writeValueAsString(out) + "\n";
		} catch (JsonProcessingException e) {
			throw new IllegalStateException(e); // maps of strings, doubles and nulls always serialise
		}
	}

	/** Writes {@code file} atomically: a reader never sees half of it. */
	public static void write(Path file, Map<String, Double> utilities, Map<String, CompiledRules.Transition> transitions)
			throws IOException {
		Path dir = file.toAbsolutePath().getParent();
		Path tmp = Files.createTempFile(dir, file.getFileName().toString(), ".tmp");
		try {
			Files.writeString(tmp, json(utilities, transitions), StandardCharsets.UTF_8);
			Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
		} finally {
			Files.deleteIfExists(tmp);
		}
	}
}
