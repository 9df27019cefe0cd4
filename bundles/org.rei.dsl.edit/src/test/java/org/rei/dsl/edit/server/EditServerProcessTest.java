/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.rei.dsl.edit.Texts;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The engine as its own process, started as the HTTP server starts it: whatever Xtext, log4j and EMF print while
 * they set up must not reach stdout, and closing stdin ends the process with 0. (The test's class path stands in
 * for rei-room-editor.jar, which is built after the tests.)
 */
class EditServerProcessTest {

	@Test
	void stdoutCarriesOnlyTheAnswersAndClosingStdinEndsTheProcess(@TempDir Path dir) throws Exception {
		Path file = dir.resolve("case.rei");
		Files.copy(Texts.repository().resolve("examples/simple_navigation.rei"), file);
		Path stdout = dir.resolve("stdout");
		Path stderr = dir.resolve("stderr");
		Process process = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
				"-cp", System.getProperty("java.class.path"), EditServer.class.getName())
				.redirectOutput(stdout.toFile()).redirectError(stderr.toFile()).start();
		try (OutputStream stdin = process.getOutputStream()) {
			ObjectMapper json = new ObjectMapper();
			String requests = "{\"id\": 1, \"command\": \"open\", \"path\": " + json.writeValueAsString(file.toString())
					+ "}\nnot json\n{\"id\": 2, \"command\": \"apply\", \"operations\": [{\"op\": \"moveObject\", "
					+ "\"name\": \"table1\", \"floor\": \"F_3_3\"}]}\n";
			stdin.write(requests.getBytes(StandardCharsets.UTF_8));
		}
		boolean ended = process.waitFor(60, TimeUnit.SECONDS);
		if (!ended) {
			process.destroyForcibly();
		}
		assertTrue(ended, "the engine goes on after stdin closed");
		String log = read(stderr);
		assertEquals(0, process.exitValue(), log);

		List<String> lines = Files.readAllLines(stdout, StandardCharsets.UTF_8);
		assertEquals(3, lines.size(), () -> "stdout:\n" + String.join("\n", lines) + "\nstderr:\n" + log);
		ObjectMapper json = new ObjectMapper();
		JsonNode opened = json.readTree(lines.get(0));
		assertTrue(opened.get("ok").asBoolean(), lines.get(0));
		JsonNode malformed = json.readTree(lines.get(1));
		assertTrue(malformed.get("id").isNull());
		assertFalse(malformed.get("ok").asBoolean());
		JsonNode moved = json.readTree(lines.get(2));
		assertEquals(2, moved.get("id").asInt());
		assertEquals("F_3_3", moved.at("/diagram/objects/0/floor").asText());
		assertTrue(log.contains("ready"), log);
	}

	private static String read(Path file) throws IOException {
		return Files.readString(file, StandardCharsets.UTF_8);
	}
}
