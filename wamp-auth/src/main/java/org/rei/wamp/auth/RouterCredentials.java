/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.wamp.auth;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.Set;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import ws.wamp.jawampa.auth.client.ClientSideAuthentication;
import ws.wamp.jawampa.auth.client.Ticket;

/**
 * One role's credentials, read from the 0600 file the router wrote ({@code --auth-file}; format
 * {@code rei-router-credentials/1}, docs/security.md). Secrets never appear on the command line.
 */
public record RouterCredentials(String authid, String method, String secret) {

	public static final String FORMAT = "rei-router-credentials/1";

	@Override
	public String toString() {
		return "RouterCredentials[authid=" + authid + ", method=" + method + ", secret=***]";
	}

	public static RouterCredentials read(Path file) throws IOException {
		try {
			Set<PosixFilePermission> mode = Files.getPosixFilePermissions(file);
			for (PosixFilePermission p : mode) {
				if (p.name().startsWith("GROUP") || p.name().startsWith("OTHERS")) {
					throw new IOException(file + ": credentials readable by other users; expected mode 600");
				}
			}
		} catch (UnsupportedOperationException e) {
			// not a POSIX file system: nothing to check
		}
		JsonNode json = new ObjectMapper().readTree(file.toFile());
		if (json == null || !FORMAT.equals(json.path("format").asText())) {
			throw new IOException(file + ": not a REI credentials file (" + FORMAT + ")");
		}
		String authid = json.path("authid").asText("");
		String method = json.path("method").asText("wampcra");
		String secret = json.path("secret").asText("");
		if (authid.isEmpty() || secret.isEmpty()) {
			throw new IOException(file + ": authid and secret are required");
		}
		if (!method.equals(WampCra.AUTH_METHOD) && !method.equals(Ticket.AUTH_METHOD)) {
			throw new IOException(file + ": authentication method " + method + " (expected wampcra or ticket)");
		}
		return new RouterCredentials(authid, method, secret);
	}

	public ClientSideAuthentication authentication() {
		return method.equals(WampCra.AUTH_METHOD) ? new WampCra(secret) : new Ticket(secret);
	}
}
