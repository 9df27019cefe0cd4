/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.conversion;

import org.eclipse.xtext.common.services.DefaultTerminalConverters;
import org.eclipse.xtext.conversion.IValueConverter;
import org.eclipse.xtext.conversion.ValueConverter;
import org.eclipse.xtext.conversion.ValueConverterException;
import org.eclipse.xtext.nodemodel.INode;

/** Converts the data type rules of the grammar; whitespace or comments inside a number are dropped. */
public class VeplValueConverters extends DefaultTerminalConverters {

	@ValueConverter(rule = "Decimal")
	public IValueConverter<Double> decimal() {
		return new IValueConverter<>() {
			@Override
			public Double toValue(String string, INode node) {
				if (string == null) {
					return null;
				}
				String text = string.replaceAll("\\s+|/\\*.*?\\*/", "");
				try {
					return Double.valueOf(text);
				} catch (NumberFormatException e) {
					throw new ValueConverterException("not a number: " + text, node, e);
				}
			}

			@Override
			public String toString(Double value) {
				return value == Math.rint(value) && !Double.isInfinite(value) ? Long.toString(value.longValue())
						: value.toString();
			}
		};
	}
}
