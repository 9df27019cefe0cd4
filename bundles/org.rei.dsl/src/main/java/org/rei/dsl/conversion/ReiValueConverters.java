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
			try {
				return Double.valueOf(text);
			} catch (NumberFormatException e) {
				throw new ValueConverterException("Expected a number but found '" + string + "'", node, e);
			}
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
