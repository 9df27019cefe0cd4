/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;


/** The environment REI passes, and the credentials file it names. */
class SutClientTest {

	private static Map<String, String> environment(Path authFile) {
		Map<String, String> env = new HashMap<>();
		env.put("REI_ROUTER_URL", "ws://127.0.0.1:1/ws");
		env.put("REI_REALM", "rei");
		env.put("REI_RUN_ID", "run-1");
		env.put("REI_AUTH_FILE", authFile.toString());
		return env;
	}

	private static Path credentials(Path dir, String mode) throws Exception {
		Path file = dir.resolve("sut.json");
		Files.writeString(file, "{\"format\":\"rei-router-credentials/1\",\"authid\":\"sut\",\"method\":\"wampcra\","
				+ "\"secret\":\"abc\"}");
		Files.setPosixFilePermissions(file, PosixFilePermissions.fromString(mode));
		return file;
	}

	@Test
	void readsTheEnvironment(@TempDir Path dir) throws Exception {
		SutClient client = SutClient.fromEnvironment(environment(credentials(dir, "rw-------")));
		assertEquals("rei.run.run-1.sut.tick", client.uri("tick"));
	}

	@Test
	void aMissingVariableIsNamed(@TempDir Path dir) throws Exception {
		Map<String, String> env = environment(credentials(dir, "rw-------"));
		env.remove("REI_RUN_ID");
		SutException e = assertThrows(SutException.class, () -> SutClient.fromEnvironment(env));
		assertEquals(SutClient.EXIT_CONNECTION, e.exitCode());
		assertTrue(e.getMessage().contains("REI_RUN_ID"), e.getMessage());
	}

	@Test
	void refusesCredentialsOthersCanRead(@TempDir Path dir) throws Exception {
		SutException e = assertThrows(SutException.class,
				() -> SutClient.fromEnvironment(environment(credentials(dir, "rw-r-----"))));
		assertEquals(SutClient.EXIT_CONNECTION, e.exitCode());
		assertTrue(e.getMessage().contains("readable by other users"), e.getMessage());
		assertFalse(e.getMessage().contains("abc"), "the secret is never printed");
		e = assertThrows(SutException.class, () -> SutClient.fromEnvironment(environment(dir.resolve("none.json"))));
		assertTrue(e.getMessage().endsWith("no such file"), e.getMessage());
	}

	@Test
	void helloNamesTheClassUnlessItHasNone() {
		class Navigator implements SystemUnderTest {
			@Override
			public Command onTick(Tick tick) {
				return Command.STOP;
			}
		}
		assertEquals("Navigator", SutClient.name(new Navigator()));
		assertEquals(null, SutClient.name(tick -> Command.STOP));
	}
}
