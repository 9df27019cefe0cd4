/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.parser;

import java.util.List;
import java.util.Set;

import org.antlr.runtime.CommonToken;
import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.Token;
import org.antlr.runtime.TokenStream;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;

/**
 * Syntax errors a test engineer can act on, where the parser's own message names only the token it did not expect:
 * a unit written after a number ({@code from 200ms}: the language reads seconds, written 5 or 5s, and plain metres
 * and degrees), and a part of the test case out of its place ({@code faults} after {@code monitor}).
 */
public class ReiSyntaxErrorMessageProvider extends SyntaxErrorMessageProvider {

	/** Words that read as a unit when written right after a number. */
	private static final Set<String> UNITS = Set.of("ms", "us", "ns", "min", "mins", "h", "hr", "sec", "secs",
			"second", "seconds", "m", "cm", "mm", "km", "deg", "degree", "degrees", "rad", "hz", "Hz");

	/** The test case's parts, in the order the grammar takes them (after its room). */
	private static final List<String> PARTS = List.of("mission", "faults", "monitor");

	@Override
	public SyntaxErrorMessage getSyntaxErrorMessage(IParserErrorContext context) {
		RecognitionException e = context.getRecognitionException();
		Token token = e == null ? null : e.token;
		if (token != null && token.getText() != null) {
			String text = token.getText();
			if (UNITS.contains(text) && afterNumber(e, token, context.getTokenNames())) {
				return new SyntaxErrorMessage("'" + text + "' is not a unit the language reads: times are seconds (5 or "
						+ "5s), distances metres and angles degrees, each a plain number", Diagnostic.SYNTAX_DIAGNOSTIC);
			}
			String message = context.getDefaultMessage();
			if (PARTS.contains(text) && message != null && message.startsWith("mismatched input '" + text + "'")) {
				return new SyntaxErrorMessage("'" + text + "' is out of place: a test case has its room, then mission, "
						+ "faults { } and monitor { } in this order, each at most once", Diagnostic.SYNTAX_DIAGNOSTIC);
			}
		}
		return super.getSyntaxErrorMessage(context);
	}

	/** Whether {@code token} is written right after a whole number (no space between: {@code 200ms}). */
	private static boolean afterNumber(RecognitionException e, Token token, String[] tokenNames) {
		if (!(e.input instanceof TokenStream tokens) || !(token instanceof CommonToken word) || token.getTokenIndex() < 1
				|| tokenNames == null) {
			return false;
		}
		Token before = tokens.get(token.getTokenIndex() - 1);
		return before instanceof CommonToken number && number.getType() >= 0 && number.getType() < tokenNames.length
				&& "RULE_INT".equals(tokenNames[number.getType()]) && number.getStopIndex() + 1 == word.getStartIndex();
	}
}
