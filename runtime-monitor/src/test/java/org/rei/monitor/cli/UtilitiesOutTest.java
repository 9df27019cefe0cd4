/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.monitor.signals.UtilitiesFile;

/** {@code --utilities-out}: the utilities the patterns in use declare, for the evaluator (docs/vepl.md). */
class UtilitiesOutTest {

	private static final String MINE = """
			atomicEvent userTaskStarts() as mission TASK_START
			signal SIG_USER_TASK_STARTED utility 7
			signal SIG_USER_UNSCORED
			rule "User: a task starts" on userTaskStarts emits SIG_USER_TASK_STARTED, SIG_USER_UNSCORED
			""";

	private record Outcome(int code, String err) {
	}

	private static Outcome run(String... args) {
		ByteArrayOutputStream err = new ByteArrayOutputStream();
		int code = Main.run(args, new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8),
				new PrintStream(err, true, StandardCharsets.UTF_8));
		return new Outcome(code, err.toString(StandardCharsets.UTF_8));
	}

	@Test
	void theDefaultsAndAUsersPatternsDeclareTheirUtilitiesNullWhereNoneIsGiven(@TempDir Path tmp) throws Exception {
		Path dir = Files.createDirectory(tmp.resolve("patterns"));
		Files.writeString(dir.resolve("mine.vepl"), MINE);
		Path file = tmp.resolve("utilities.json");
		Outcome o = run("--compile-only", "--patterns", dir.toString(), "--utilities-out", file.toString());
		assertEquals(0, o.code(), o.err());
		String json = Files.readString(file);
		// declaration order (files by name: contacts.vepl first), with the zone changes the default patterns declare
		assertTrue(json.startsWith("{\"SIG_OBJECT_COLLISION_BEGIN\":{\"utility\":0.0,\"transition\":{"), json);
		assertTrue(json.contains("\"per_object\":true"), json);
		assertTrue(json.contains("\"SIG_GEOM_FAR_TRANSIT_CLOSE\":{\"utility\":-2.0,\"transition\":{\"source\":\"GEOM\","
				+ "\"from\":\"FAR\",\"to\":\"CLOSE\"}}"), json);
		assertTrue(json.contains("\"SIG_MISSION_TASK_FAIL\":{\"utility\":-100.0}"), json);
		assertTrue(json.contains("\"SIG_LASER_FAR_TRANSIT_CLOSE\":{\"utility\":null,\"transition\":{"), json);
		assertTrue(json.endsWith("\"SIG_USER_TASK_STARTED\":{\"utility\":7.0},\"SIG_USER_UNSCORED\":{\"utility\":null}}\n"),
				json);
	}

	@Test
	void withoutTheDefaultsOnlyTheUsersSignals(@TempDir Path tmp) throws Exception {
		Path dir = Files.createDirectory(tmp.resolve("patterns"));
		Files.writeString(dir.resolve("mine.vepl"), MINE);
		Path file = tmp.resolve("utilities.json");
		Outcome o = run("--compile-only", "--patterns", dir.toString(), "--no-default-patterns", "--utilities-out",
				file.toString());
		assertEquals(0, o.code(), o.err());
		assertEquals("{\"SIG_USER_TASK_STARTED\":{\"utility\":7.0},\"SIG_USER_UNSCORED\":{\"utility\":null}}\n",
				Files.readString(file));
	}

	@Test
	void handWrittenRulesDeclareNothing(@TempDir Path tmp) throws Exception {
		Path dir = Files.createDirectory(tmp.resolve("rules"));
		Files.writeString(dir.resolve("mine.drl"), "package org.rei.monitor.rules;\n");
		Path file = tmp.resolve("utilities.json");
		Outcome o = run("--compile-only", "--rules", dir.toString(), "--utilities-out", file.toString());
		assertEquals(0, o.code(), o.err());
		assertEquals("{}\n", Files.readString(file));
	}

	@Test
	void invalidPatternsFailWithFileLineAndColumnAndWriteNothing(@TempDir Path tmp) throws Exception {
		Path dir = Files.createDirectory(tmp.resolve("patterns"));
		Files.writeString(dir.resolve("bad.vepl"), "\nqueryEvent x() as noSuchQuery found\n");
		Path file = tmp.resolve("utilities.json");
		Outcome o = run("--compile-only", "--patterns", dir.toString(), "--utilities-out", file.toString());
		assertEquals(1, o.code(), o.err());
		assertTrue(o.err().contains("bad.vepl:2:19: Unknown query 'noSuchQuery'"), o.err());
		assertFalse(o.err().contains("VeplException"), o.err()); // the message, not the exception's class
		assertFalse(Files.exists(file));
	}

	@Test
	void compileOnlyIsItsOwnMode() {
		Outcome o = run("--compile-only", "--replay", "out", "--case", "c");
		assertEquals(2, o.code(), o.err());
		assertTrue(o.err().contains("--compile-only starts neither live mode nor a replay"), o.err());
		Main.Options parsed = Main.Options.parse(new String[] { "--router", "ws://127.0.0.1:9/ws", "--run", "r",
				"--utilities-out", "u.json" });
		assertEquals(Path.of("u.json"), parsed.utilitiesOut);
	}

	@Test
	void theJsonKeepsTheOrderAndTheNulls() {
		Map<String, Double> m = new LinkedHashMap<>();
		m.put("SIG_B", 1.5);
		m.put("SIG_A", null);
		Map<String, org.rei.vepl.compiler.CompiledRules.Transition> t = Map.of("SIG_A",
				new org.rei.vepl.compiler.CompiledRules.Transition("LASER", "CLOSE", "FAR", false));
		String json = UtilitiesFile.json(m, t);
		assertTrue(json.startsWith("{\"SIG_B\":{\"utility\":1.5},\"SIG_A\":{\"utility\":null,\"transition\":{"), json);
		assertTrue(json.contains("\"source\":\"LASER\"") && json.contains("\"from\":\"CLOSE\"")
				&& json.contains("\"to\":\"FAR\""), json);
		assertEquals("{}\n", UtilitiesFile.json(Map.of(), Map.of()));
	}
}
