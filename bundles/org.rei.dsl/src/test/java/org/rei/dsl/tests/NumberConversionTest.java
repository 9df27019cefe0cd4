/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import com.google.inject.Inject;

/** Numbers an editor writes into a case are read back as the same numbers (the room editor's edits serialize). */
@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class NumberConversionTest {

	@Inject
	private IValueConverterService converters;

	@ParameterizedTest
	@ValueSource(doubles = { 0.0001, 0.00025, 0.5, 1.25, 3.0, 12345678.5, 1.0E7 })
	void aNumberIsWrittenWithoutAnExponentAndReadsBack(double value) {
		for (String rule : new String[] { "Number", "Duration" }) {
			String text = converters.toString(value, rule);
			assertEquals(-1, text.indexOf('E'), rule + " " + value + " written as " + text);
			assertEquals(value, (Double) converters.toValue(text, rule, null), 0.0, rule + " " + text);
		}
	}
}
