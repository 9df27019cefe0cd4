/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class NumbersTest {

	@Test
	void neverAnExponent() {
		assertEquals("0.0001", Numbers.format(1e-4));
		assertEquals("12345678901234.5", Numbers.format(12345678901234.5));
	}

	@Test
	void atLeastOneAndAtMostSixDecimals() {
		assertEquals("2.0", Numbers.format(2));
		assertEquals("1.234568", Numbers.format(1.23456789));
		assertEquals("-0.005", Numbers.format(-0.005));
		assertEquals("0.1", Numbers.format(0.1 + 0.2 - 0.2));
	}

	@Test
	void noNegativeZero() {
		assertEquals("0.0", Numbers.format(-0.0));
		assertEquals("0.0", Numbers.format(-1e-9));
	}

	@Test
	void rejectsWhatJsonCannotHold() {
		assertThrows(IllegalArgumentException.class, () -> Numbers.format(Double.NaN));
		assertThrows(IllegalArgumentException.class, () -> Numbers.format(Double.POSITIVE_INFINITY));
	}
}
