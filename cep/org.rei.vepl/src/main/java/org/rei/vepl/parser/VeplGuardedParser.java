/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.parser;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import org.antlr.runtime.CharStream;
import org.antlr.runtime.CommonToken;
import org.antlr.runtime.Token;
import org.antlr.runtime.TokenSource;
import org.apache.log4j.Logger;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.nodemodel.impl.NodeModelBuilder;
import org.eclipse.xtext.parser.IParseResult;
import org.eclipse.xtext.parser.ParseResult;
import org.rei.vepl.parser.antlr.VeplParser;
import org.rei.vepl.validation.VeplIssueCodes;

/**
 * VEPL's parser, which never throws and never recurses without bound. ANTLR's parser descends once per bracket, so
 * brackets nested deeper than {@link #MAX_NESTING} are refused from the tokens, before the parser sees them: one
 * syntax error ({@link VeplIssueCodes#TOO_DEEP}) on the first bracket too many. A chain of operators is a loop in
 * the parser but one level of the model per operator ({@code a -> b -> c} is {@code (a -> b) -> c}), and scoping
 * and validation recurse along the model: more than {@link #MAX_OPERATORS} in one declaration are refused the same
 * way. The lexer is a loop, and it knows comments and strings, so a bracket in them does not count. Whatever else
 * fails while parsing, in the guard (its lexer, the grammar's token definitions) or in the parser, is logged and
 * becomes a syntax error of the file too ({@link VeplIssueCodes#UNREADABLE}), so one file can stop neither a build
 * of the language server nor the loader's report of the other files.
 */
public class VeplGuardedParser extends VeplParser {

	/** Brackets nested deeper than any pattern needs; the parser recurses once per level. */
	public static final int MAX_NESTING = 100;

	/** Operators ({@code ->}, {@code AND}, {@code OR}) in one declaration, far more than any pattern needs. */
	public static final int MAX_OPERATORS = 200;

	private static final Logger LOG = Logger.getLogger(VeplGuardedParser.class);

	private Set<Integer> opening;
	private Set<Integer> closing;
	private Set<Integer> operator;
	private Set<Integer> declaring;

	@Override
	protected IParseResult doParse(String ruleName, CharStream in, NodeModelBuilder builder, int initialLookAhead) {
		int start = in.mark();
		try {
			IParseResult refusal = refusal(createLexer(in), in);
			in.rewind(start);
			return refusal != null ? refusal : super.doParse(ruleName, in, builder, initialLookAhead);
		} catch (RuntimeException | StackOverflowError e) {
			LOG.error("VEPL parser failed; the file gets a syntax error instead", e);
			return refused(in, null, "The file could not be parsed (" + e + "): please report it with the file",
					VeplIssueCodes.UNREADABLE);
		}
	}

	/** Every edit parses the whole file: a partial reparse of one bracket's content would not see its depth. */
	@Override
	protected boolean isReparseSupported() {
		return false;
	}

	/** The refusal of the first bracket beyond {@link #MAX_NESTING} or operator beyond {@link #MAX_OPERATORS}. */
	private IParseResult refusal(TokenSource lexer, CharStream in) {
		tokenTypes();
		int depth = 0;
		int operators = 0;
		for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
			int type = t.getType();
			if (opening.contains(type) && ++depth > MAX_NESTING) {
				return refused(in, (CommonToken) t, "Brackets nested deeper than " + MAX_NESTING
						+ " levels: the file is not parsed (no pattern needs that many)", VeplIssueCodes.TOO_DEEP);
			} else if (closing.contains(type) && depth > 0) { // a stray closing bracket is the parser's to report
				depth--;
			} else if (declaring.contains(type)) {
				operators = 0;
			} else if (operator.contains(type) && ++operators > MAX_OPERATORS) {
				return refused(in, (CommonToken) t, "More than " + MAX_OPERATORS + " operators (->, AND, OR) in one "
						+ "declaration: the file is not parsed (no pattern needs that many)", VeplIssueCodes.TOO_DEEP);
			}
		}
		return null;
	}

	/** The tokens the guard needs, by kind, as the grammar's token definitions name them. */
	private static final Map<String, List<String>> KINDS = Map.of(
			"opening", List.of("'('", "'{'", "'['"),
			"closing", List.of("')'", "'}'", "']'"),
			"operator", List.of("'->'", "'AND'", "'OR'"),
			"declaring", List.of("'queryEvent'", "'atomicEvent'", "'complexEvent'", "'signal'", "'rule'"));

	/**
	 * The token types of the brackets, operators and declaration keywords, from the grammar's token definitions.
	 * A token the grammar no longer defines (renamed) would silently leave the guard without it, so it is an
	 * {@link IllegalStateException} naming it, which {@link #doParse} makes every file's error.
	 */
	private synchronized void tokenTypes() {
		if (opening != null) {
			return;
		}
		Map<String, Integer> types = new HashMap<>();
		getTokenDefProvider().getTokenDefMap().forEach((type, name) -> types.put(name, type));
		List<String> missing = KINDS.values().stream().flatMap(List::stream).filter(t -> !types.containsKey(t))
				.sorted().toList();
		if (!missing.isEmpty()) {
			throw new IllegalStateException("the VEPL grammar defines no token " + String.join(", ", missing)
					+ ", which the nesting guard counts (VeplGuardedParser.KINDS)");
		}
		Map<String, Set<Integer>> byKind = new HashMap<>();
		KINDS.forEach((kind, names) -> byKind.put(kind,
				names.stream().map(types::get).collect(Collectors.toUnmodifiableSet())));
		closing = byKind.get("closing");
		operator = byKind.get("operator");
		declaring = byKind.get("declaring");
		opening = byKind.get("opening");
	}

	/**
	 * A parse result without a model whose node model is the text with one syntax error: on {@code at}, else on
	 * the first character. Nothing else of the file is checked until the error is gone.
	 */
	private IParseResult refused(CharStream in, CommonToken at, String message, String code) {
		String text = in.size() == 0 ? "" : in.substring(0, in.size() - 1);
		int from = at == null ? 0 : at.getStartIndex();
		int to = at == null ? Math.min(1, text.length()) : at.getStopIndex() + 1;
		NodeModelBuilder builder = createNodeModelBuilder();
		// under the entry rule, as the parser builds it: editor services (completion) look for it at the root
		ICompositeNode file = builder.newCompositeNode(getGrammarAccess().getPatternFileRule(), 0,
				builder.newRootNode(text));
		var hidden = getGrammarAccess().getWSRule();
		if (from > 0) {
			builder.newLeafNode(0, from, hidden, true, null, file);
		}
		builder.newLeafNode(from, to - from, getGrammarAccess().getANY_OTHERRule(), false,
				new SyntaxErrorMessage(message, code), file);
		if (to < text.length()) {
			builder.newLeafNode(to, text.length() - to, hidden, true, null, file);
		}
		return new ParseResult(null, builder.compressAndReturnParent(file), true);
	}
}
