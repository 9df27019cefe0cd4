/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * Stable decimal rendering of doubles: at most 6 decimals, at least one, never an exponent, never "-0.0".
 * Readers in other languages parse these, so output must not depend on {@link Double#toString}'s choices.
 */
public final class Numbers {

	private static final long SCALE = 1_000_000L;

	/** Beyond this the fast path could overflow a long. */
	private static final double FAST_LIMIT = 9.0e12;

	private Numbers() {
	}

	/** Renders a finite double, rounded half away from zero to 6 decimals. */
	public static String format(double value) {
		if (!Double.isFinite(value)) {
			throw new IllegalArgumentException("not a finite number: " + value);
		}
		if (Math.abs(value) >= FAST_LIMIT) {
			String s = BigDecimal.valueOf(value).setScale(6, RoundingMode.HALF_UP).stripTrailingZeros().toPlainString();
			return s.contains(".") ? s : s + ".0";
		}
		long scaled = Math.round(Math.abs(value) * SCALE);
		StringBuilder sb = new StringBuilder(12);
		if (value < 0 && scaled != 0) {
			sb.append('-');
		}
		sb.append(scaled / SCALE).append('.');
		long fraction = scaled % SCALE;
		if (fraction == 0) {
			return sb.append('0').toString();
		}
		String digits = Long.toString(fraction + SCALE).substring(1); // zero-padded to 6 digits
		int end = digits.length();
		while (digits.charAt(end - 1) == '0') {
			end--;
		}
		return sb.append(digits, 0, end).toString();
	}
}
