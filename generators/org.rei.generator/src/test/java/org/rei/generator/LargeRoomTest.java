/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** A room of benchmark size generates completely; its speed is measured by benchmarks/generation.py, not here. */
class LargeRoomTest {

	@TempDir
	Path out;

	@Test
	void tenThousandFloors() throws Exception {
		new ArtifactGenerator(GeneratorOptions.defaults()).generate(TestCases.grid(100, 100), out);

		JsonNode world = new ObjectMapper().readTree(out.resolve("world.json").toFile());
		assertEquals(10_000, world.get("floors").size());
		assertEquals(10_000 + 400, world.get("objects").size());
	}
}
