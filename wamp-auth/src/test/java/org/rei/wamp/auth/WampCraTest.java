/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.wamp.auth;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import ws.wamp.jawampa.WampMessages.ChallengeMessage;

/** WAMP-CRA as autobahn computes it (vectors from autobahn.wamp.auth.compute_wcs / derive_key). */
class WampCraTest {

	private static final ObjectMapper JSON = new ObjectMapper();

	@Test
	void signsTheChallengeWithTheSecret() {
		ObjectNode extra = JSON.createObjectNode().put("challenge", "{\"nonce\":\"abc\"}");
		String signature = new WampCra("s3cret").handleChallenge(new ChallengeMessage("wampcra", extra), JSON).signature;
		assertEquals("RYs8lh7JQ8L4Gr2sT0yDvxnP97hn2sMDl/USbTUjXvQ=", signature);
	}

	@Test
	void derivesASaltedKeyAsAutobahn() {
		byte[] key = WampCra.deriveKey("s3cret", "salt123", 1000, 32);
		assertEquals("kQjmN43OnKui4LgoWayDmOtXz3ormJk/XpUx6+QDwOk=", new String(key, StandardCharsets.US_ASCII));
		ObjectNode extra = JSON.createObjectNode().put("challenge", "chal").put("salt", "salt123")
				.put("iterations", 1000).put("keylen", 32);
		assertEquals("e8dNO/K0hyquAjr25N2R2J1hySuuX0AfY8I7nT6xUQE=",
				new WampCra("s3cret").handleChallenge(new ChallengeMessage("wampcra", extra), JSON).signature);
	}

	@Test
	void credentialsFilesMustBePrivate(@TempDir Path dir) throws IOException {
		Path file = dir.resolve("monitor.json");
		Files.writeString(file, "{\"format\":\"rei-router-credentials/1\",\"authid\":\"monitor\",\"method\":\"wampcra\","
				+ "\"secret\":\"abc\"}");
		Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
		RouterCredentials credentials = RouterCredentials.read(file);
		assertEquals("monitor", credentials.authid());
		assertFalse(credentials.toString().contains("abc"), "the secret is never printed");
		Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
		assertThrows(IOException.class, () -> RouterCredentials.read(file));
	}
}
