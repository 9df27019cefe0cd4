/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.wamp.auth;

import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.util.Base64;

import javax.crypto.Mac;
import javax.crypto.SecretKeyFactory;
import javax.crypto.spec.PBEKeySpec;
import javax.crypto.spec.SecretKeySpec;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import ws.wamp.jawampa.WampMessages.AuthenticateMessage;
import ws.wamp.jawampa.WampMessages.ChallengeMessage;
import ws.wamp.jawampa.auth.client.ClientSideAuthentication;

/**
 * WAMP-CRA (challenge-response) for jawampa, which ships only {@code Ticket}: the signature is
 * base64(HMAC-SHA256(key, challenge)), the key being the secret or, when the router sends a salt, its PBKDF2-SHA256
 * derivation (as autobahn's {@code derive_key}). The secret never crosses the wire.
 */
public final class WampCra implements ClientSideAuthentication {

	public static final String AUTH_METHOD = "wampcra";

	private final String secret;

	public WampCra(String secret) {
		this.secret = secret;
	}

	@Override
	public String getAuthMethod() {
		return AUTH_METHOD;
	}

	@Override
	public AuthenticateMessage handleChallenge(ChallengeMessage message, ObjectMapper objectMapper) {
		JsonNode extra = message.extra;
		String challenge = extra == null || !extra.hasNonNull("challenge") ? "" : extra.get("challenge").asText();
		byte[] key = secret.getBytes(StandardCharsets.UTF_8);
		if (extra != null && extra.hasNonNull("salt")) {
			key = deriveKey(secret, extra.get("salt").asText(), extra.path("iterations").asInt(1000),
					extra.path("keylen").asInt(32));
		}
		return new AuthenticateMessage(sign(key, challenge), objectMapper.createObjectNode());
	}

	/** base64(HMAC-SHA256(key, challenge)). */
	static String sign(byte[] key, String challenge) {
		try {
			Mac mac = Mac.getInstance("HmacSHA256");
			mac.init(new SecretKeySpec(key, "HmacSHA256"));
			return Base64.getEncoder().encodeToString(mac.doFinal(challenge.getBytes(StandardCharsets.UTF_8)));
		} catch (GeneralSecurityException e) {
			throw new IllegalStateException("HmacSHA256 unavailable", e);
		}
	}

	/** The salted key as autobahn derives it: the base64 text of PBKDF2-HMAC-SHA256, as bytes. */
	static byte[] deriveKey(String secret, String salt, int iterations, int keylen) {
		try {
			SecretKeyFactory factory = SecretKeyFactory.getInstance("PBKDF2WithHmacSHA256");
			byte[] raw = factory.generateSecret(new PBEKeySpec(secret.toCharArray(),
					salt.getBytes(StandardCharsets.UTF_8), iterations, keylen * 8)).getEncoded();
			return Base64.getEncoder().encodeToString(raw).getBytes(StandardCharsets.US_ASCII);
		} catch (GeneralSecurityException e) {
			throw new IllegalStateException("PBKDF2WithHmacSHA256 unavailable", e);
		}
	}
}
