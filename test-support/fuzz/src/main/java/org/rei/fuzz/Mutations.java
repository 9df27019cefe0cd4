/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.fuzz;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.BiFunction;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Mutations of a source text, each returning {name, mutated text}: bit flips, truncation, token deletion,
 * duplication and swaps, extreme numbers and names, junk characters, deep nesting, splices and broken UTF-8; plus,
 * optionally, the language's own (e.g. the DSL's room sizes).
 */
public final class Mutations {

	private static final Pattern TOKEN = Pattern.compile("\"[^\"]*\"|[A-Za-z_][A-Za-z0-9_]*|-?\\d+(\\.\\d+)?|//[^\\n]*|\\S");
	private static final String[] NUMBERS = { "99999999999999999999", "2147483647", "-2147483648", "1" + "0".repeat(400),
			"0", "-0", "100000", "0.00000000000000000001", "1.7976931348623157", "-1" };
	private static final String[] JUNK = { "\0", "\uFEFF", "\uFFFF", "\uD800", "\"", "//", "/*", "{", "}", "[", "]", "@",
			"\r", "\t\u00A0", "'", "\\" };

	private final BiFunction<String, Random, String[]> own;

	/** The generic mutations only. */
	public Mutations() {
		this(null);
	}

	/** With the language's own mutation, chosen as often as each generic one. */
	public Mutations(BiFunction<String, Random, String[]> own) {
		this.own = own;
	}

	public String[] apply(String text, Random r) {
		switch (r.nextInt(own == null ? 11 : 12)) {
		case 0: {
			if (text.isEmpty()) {
				return new String[] { "flip", text };
			}
			char[] c = text.toCharArray();
			int n = 1 + r.nextInt(4);
			for (int i = 0; i < n; i++) {
				int at = r.nextInt(c.length);
				c[at] = (char) (c[at] ^ (1 << r.nextInt(8)));
			}
			return new String[] { "flip", new String(c) };
		}
		case 1:
			return new String[] { "truncate", text.substring(0, r.nextInt(text.length() + 1)) };
		case 2:
		case 3:
		case 4:
			return tokens(text, r);
		case 5:
			return replace(text, r, Pattern.compile("\\d+(\\.\\d+)?"), NUMBERS, "number");
		case 6:
			return replace(text, r, Pattern.compile("\\b[A-Za-z_][A-Za-z0-9_]*\\b"), new String[] {
					"X".repeat(10_000 + r.nextInt(50_000)), "s", "x", "é_ü", "\u0000", "\uD83D\uDE00", "\uD800",
					"ab\u202Ecd", "𝔘𝔫𝔦𝔠𝔬𝔡𝔢" }, "name");
		case 7: {
			int at = text.isEmpty() ? 0 : r.nextInt(text.length());
			return new String[] { "insert", text.substring(0, at) + JUNK[r.nextInt(JUNK.length)] + text.substring(at) };
		}
		case 8: {
			int at = text.isEmpty() ? 0 : r.nextInt(text.length());
			String open = r.nextBoolean() ? "{" : r.nextBoolean() ? "[" : "(";
			return new String[] { "nest", text.substring(0, at) + open.repeat(1 + r.nextInt(3000)) + text.substring(at) };
		}
		case 9: {
			if (text.isEmpty()) {
				return new String[] { "splice", text };
			}
			int a = r.nextInt(text.length());
			int b = Math.min(text.length(), a + r.nextInt(200));
			int at = r.nextInt(text.length());
			return new String[] { "splice", text.substring(0, at) + text.substring(a, b) + text.substring(at) };
		}
		case 10: {
			// byte-level: re-decode mutated UTF-8, as a file with broken encoding would be read
			byte[] b = text.getBytes(StandardCharsets.UTF_8);
			if (b.length > 0) {
				b[r.nextInt(b.length)] = (byte) r.nextInt(256);
			}
			return new String[] { "bytes", new String(b, StandardCharsets.UTF_8) };
		}
		default:
			return own.apply(text, r);
		}
	}

	private static String[] tokens(String text, Random r) {
		List<String> tokens = new ArrayList<>();
		Matcher m = TOKEN.matcher(text);
		while (m.find()) {
			tokens.add(m.group());
		}
		if (tokens.size() < 2) {
			return new String[] { "tokens", text };
		}
		int i = r.nextInt(tokens.size());
		int j = r.nextInt(tokens.size());
		String name;
		switch (r.nextInt(3)) {
		case 0 -> {
			tokens.remove(i);
			name = "token-delete";
		}
		case 1 -> {
			tokens.add(i, tokens.get(j));
			name = "token-duplicate";
		}
		default -> {
			String t = tokens.get(i);
			tokens.set(i, tokens.get(j));
			tokens.set(j, t);
			name = "token-swap";
		}
		}
		return new String[] { name, String.join(" ", tokens) };
	}

	private static String[] replace(String text, Random r, Pattern p, String[] values, String name) {
		List<int[]> spans = new ArrayList<>();
		Matcher m = p.matcher(text);
		while (m.find()) {
			spans.add(new int[] { m.start(), m.end() });
		}
		if (spans.isEmpty()) {
			return new String[] { name, text };
		}
		int[] s = spans.get(r.nextInt(spans.size()));
		return new String[] { name, text.substring(0, s[0]) + values[r.nextInt(values.length)] + text.substring(s[1]) };
	}
}
