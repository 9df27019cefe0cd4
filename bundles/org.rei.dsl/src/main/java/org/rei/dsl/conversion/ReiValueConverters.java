/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.conversion;

import java.math.BigDecimal;

import org.eclipse.xtext.common.services.DefaultTerminalConverters;
import org.eclipse.xtext.conversion.IValueConverter;
import org.eclipse.xtext.conversion.ValueConverter;
import org.eclipse.xtext.conversion.ValueConverterException;
import org.eclipse.xtext.conversion.impl.AbstractNullSafeConverter;
import org.eclipse.xtext.nodemodel.INode;

/** Converts the numbers of the language: plain decimals and durations with an optional "s" unit. */
public class ReiValueConverters extends DefaultTerminalConverters {

	@ValueConverter(rule = "Number")
	public IValueConverter<Double> number() {
		return new DecimalConverter("");
	}

	@ValueConverter(rule = "Duration")
	public IValueConverter<Double> duration() {
		return new DecimalConverter("s");
	}

	/** Whole numbers; one too large for an int says so (the default converter's message was "For input string"). */
	@Override
	@ValueConverter(rule = "INT")
	public IValueConverter<Integer> INT() {
		IValueConverter<Integer> base = super.INT();
		return new IValueConverter<>() {
			@Override
			public Integer toValue(String string, INode node) {
				String text = string == null ? "" : string.strip();
				if (!text.isEmpty() && text.chars().allMatch(Character::isDigit)) {
					try {
						return Integer.valueOf(text);
					} catch (NumberFormatException e) {
						// no cause: the parser reports a cause's message instead of this one
						throw new ValueConverterException("Expected a whole number of at most " + Integer.MAX_VALUE
								+ " but found '" + text + "'", node, null);
					}
				}
				return base.toValue(string, node);
			}

			@Override
			public String toString(Integer value) {
				return base.toString(value);
			}
		};
	}

	private static final class DecimalConverter extends AbstractNullSafeConverter<Double> {
		private final String unit;

		DecimalConverter(String unit) {
			this.unit = unit;
		}

		@Override
		public Double toValue(String string, INode node) {
			// Error recovery may hand over nothing where a number is missing: say what was expected.
			if (string == null || string.isBlank()) {
				throw new ValueConverterException("Expected a number" + (unit.isEmpty() ? "" : " of seconds"), node,
						null);
			}
			return super.toValue(string, node);
		}

		@Override
		protected Double internalToValue(String string, INode node) {
			String text = string.strip();
			if (!unit.isEmpty() && text.endsWith(unit)) {
				text = text.substring(0, text.length() - unit.length()).strip();
			}
			double value;
			try {
				value = Double.parseDouble(text);
			} catch (NumberFormatException e) {
				throw new ValueConverterException("Expected a number but found '" + string + "'", node, e);
			}
			// hundreds of digits read as Infinity, which no check compares and the generator cannot write
			if (!Double.isFinite(value)) {
				throw new ValueConverterException("Expected a finite number but found '" + string + "'", node, null);
			}
			return value;
		}

		@Override
		protected String internalToString(Double value) {
			// never Double.toString: below 0.001 or from 10^7 on it writes an exponent (1.0E-4), which the
			// language does not read, so an editor's edit would not read back
			String text = value == Math.rint(value) && !Double.isInfinite(value)
					? Long.toString(value.longValue())
					: BigDecimal.valueOf(value).toPlainString();
			return unit.isEmpty() ? text : text + unit;
		}
	}
}
