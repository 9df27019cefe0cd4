/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.StreamSupport;

import org.antlr.runtime.CharStream;
import org.antlr.runtime.TokenSource;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.parser.IParseResult;
import org.eclipse.xtext.parser.antlr.ITokenDefProvider;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.rei.vepl.compiler.VeplLoader;
import org.rei.vepl.parser.VeplGuardedParser;
import org.rei.vepl.validation.KnownQueries;
import org.rei.vepl.validation.VeplIssueCodes;

import com.google.inject.Inject;
import com.google.inject.Injector;
import com.google.inject.Provider;

/**
 * The checks of the whole file that the loader used to make on its own, now the validator's (so an editor shows
 * them too): brackets nested deeper than {@link VeplGuardedParser#MAX_NESTING}, refused before the parser recurses;
 * a file that declares nothing; a name declared in two files loaded together. The loader reports them for every
 * file.
 */
@ExtendWith(InjectionExtension.class)
@InjectWith(VeplInjectorProvider.class)
class NestingLimitTest {

	private static final String EVENT = "queryEvent a as robotFar found\n";

	@Inject
	private Provider<XtextResourceSet> resourceSets;

	@Inject
	private IResourceValidator validator;

	@Inject
	private Injector injector;

	/** A complex event on line 2 whose expression is {@code a} inside {@code parens} brackets ('{' is one more). */
	private static String nested(int parens) {
		return EVENT + "complexEvent c() { as " + "(".repeat(parens) + "a" + ")".repeat(parens) + " }\n";
	}

	/** The errors of one file, each as {@code line:column code}, checked as the language server checks it. */
	private List<String> errors(String text) {
		XtextResourceSet set = resourceSets.get();
		KnownQueries.attach(set, KnownQueries.defaults());
		Resource r = set.createResource(URI.createURI("test:/p.vepl"));
		try {
			r.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), null);
		} catch (IOException e) {
			throw new AssertionError(e);
		}
		return validator.validate(r, CheckMode.ALL, CancelIndicator.NullImpl).stream()
				.filter(i -> i.getSeverity() == Severity.ERROR)
				.map(i -> i.getLineNumber() + ":" + i.getColumn() + " " + i.getCode()).toList();
	}

	@Test
	void theLimitItselfParsesAndOneMoreIsRefusedOnTheFirstBracketTooMany() {
		assertEquals(List.of(), errors(nested(VeplGuardedParser.MAX_NESTING - 1)));
		// "complexEvent c() { as " is 22 characters: the brace is level 1, the 100th '(' level 101, column 122
		assertEquals(List.of("2:122 " + VeplIssueCodes.TOO_DEEP), errors(nested(VeplGuardedParser.MAX_NESTING)));
	}

	@Test
	void deepAndUnbalancedNestingIsOneErrorQuickly() {
		assertTimeoutPreemptively(Duration.ofSeconds(20), () -> {
			for (int depth : new int[] { 1_000, 3_000, 100_000 }) {
				assertEquals(List.of("2:122 " + VeplIssueCodes.TOO_DEEP), errors(nested(depth)), "depth " + depth);
			}
			String open = EVENT + "complexEvent c() { as " + "(".repeat(3_000) + "\n";
			assertEquals(List.of("2:122 " + VeplIssueCodes.TOO_DEEP), errors(open));
			assertEquals(List.of("1:101 " + VeplIssueCodes.TOO_DEEP), errors("[{(".repeat(1_000)));
		});
	}

	@Test
	void aChainOfMoreOperatorsThanTheLimitIsRefusedOnTheFirstOneTooMany() {
		String chain = EVENT + "complexEvent c() { as a" + " -> a".repeat(VeplGuardedParser.MAX_OPERATORS) + " }\n";
		assertEquals(List.of(), errors(chain));
		assertTimeoutPreemptively(Duration.ofSeconds(20), () -> {
			for (int operators : new int[] { VeplGuardedParser.MAX_OPERATORS + 1, 20_000 }) {
				String text = EVENT + "complexEvent c() { as a" + " AND a".repeat(operators) + " }\n";
				// "complexEvent c() { as a" is 23 characters, each " AND a" 6: the 201st AND is at 25 + 200 * 6
				assertEquals(List.of("2:" + (25 + VeplGuardedParser.MAX_OPERATORS * 6) + " " + VeplIssueCodes.TOO_DEEP),
						errors(text), "operators " + operators);
			}
		});
		String many = EVENT + ("complexEvent c() { as a" + " OR a".repeat(150) + " }\n").repeat(2).replaceFirst("c\\(", "d(");
		assertEquals(List.of(), errors(many)); // the limit is per declaration
	}

	@Test
	void bracketsInCommentsAndStringsDoNotCount() {
		String text = "/* " + "(".repeat(500) + " */\n// " + "{".repeat(500) + "\n" + EVENT + "signal S\n"
				+ "rule \"" + "[".repeat(500) + "\" on a emits S\n";
		assertEquals(List.of(), errors(text));
		String deepAfterComment = "/* ((((( */ " + nested(VeplGuardedParser.MAX_NESTING);
		assertEquals(List.of("2:122 " + VeplIssueCodes.TOO_DEEP), errors(deepAfterComment));
	}

	@Test
	void aFileWithoutAnyDeclarationIsAnErrorWithOrWithoutAModel() {
		for (String text : new String[] { "", "   \n", "// nothing\n/* at all */", "package a.b\n" }) {
			assertEquals(List.of("1:1 " + VeplIssueCodes.EMPTY_FILE), errors(text), () -> "'" + text + "'");
		}
	}

	@Test
	void theLoaderReportsEveryFilesErrorsWithFileLineAndColumn() {
		var e = assertThrows(VeplLoader.VeplException.class, () -> VeplLoader.load(List.of(
				new VeplLoader.Source("deep.vepl", nested(3_000)),
				new VeplLoader.Source("unknown.vepl", "\nqueryEvent x as noSuchQuery found\n"),
				new VeplLoader.Source("empty.vepl", "")), KnownQueries.defaults()));
		String message = e.getMessage();
		assertTrue(message.contains("\n  deep.vepl:2:122: Brackets nested deeper than 100 levels"), message);
		assertTrue(message.contains("[" + VeplIssueCodes.TOO_DEEP + "]"), message);
		assertTrue(message.contains("\n  unknown.vepl:2:17: Unknown query 'noSuchQuery'"), message);
		assertTrue(message.contains("\n  empty.vepl:1:1: The file declares no event"), message);
		assertEquals(4, message.split("\n").length, message);
	}

	@Test
	void aNameDeclaredInTwoLoadedFilesIsAnErrorInBoth() {
		var e = assertThrows(VeplLoader.VeplException.class, () -> VeplLoader.load(List.of(
				new VeplLoader.Source("one.vepl", EVENT + "signal S\n"),
				new VeplLoader.Source("two.vepl", "signal T\n" + EVENT)), KnownQueries.defaults()));
		String message = e.getMessage();
		assertTrue(message.contains("\n  one.vepl:1:12: Duplicate name 'a': event a is also declared in two.vepl on "
				+ "line 2"), message);
		assertTrue(message.contains("\n  two.vepl:2:12: Duplicate name 'a': event a is also declared in one.vepl on "
				+ "line 1"), message);
		assertEquals(3, message.split("\n").length, message);
	}

	/** The syntax errors of a parse by {@code parser}, which must answer and not throw, each as "code: message". */
	private static List<String> parseErrors(VeplGuardedParser parser, String text) {
		IParseResult result = parser.parse(new StringReader(text));
		assertTrue(result.hasSyntaxErrors(), text);
		return StreamSupport.stream(result.getSyntaxErrors().spliterator(), false).map(INode::getSyntaxErrorMessage)
				.map(m -> m.getIssueCode() + ": " + m.getMessage()).toList();
	}

	/** A grammar whose token for {@code AND} is renamed: the guard cannot be built, and says so as the file's error. */
	@Test
	void aGuardThatCannotBeBuiltIsTheFilesErrorNotAnException() {
		VeplGuardedParser parser = new VeplGuardedParser() {
			@Override
			public ITokenDefProvider getTokenDefProvider() {
				ITokenDefProvider real = super.getTokenDefProvider();
				Map<Integer, String> renamed = real.getTokenDefMap().entrySet().stream()
						.filter(e -> !e.getValue().equals("'AND'"))
						.collect(Collectors.toMap(Map.Entry::getKey, Map.Entry::getValue));
				return new ITokenDefProvider() {
					@Override
					public Map<Integer, String> getTokenDefMap() {
						return renamed;
					}
				};
			}
		};
		injector.injectMembers(parser);
		List<String> errors = parseErrors(parser, EVENT);
		assertEquals(1, errors.size(), errors::toString);
		assertTrue(errors.get(0).startsWith(VeplIssueCodes.UNREADABLE + ": "), errors::toString);
		assertTrue(errors.get(0).contains("the VEPL grammar defines no token 'AND'"), errors::toString);
	}

	/** A lexer that fails while the guard reads the tokens: the file's error, not an exception out of the parser. */
	@Test
	void aLexerFailureInTheGuardIsTheFilesErrorNotAnException() {
		VeplGuardedParser parser = new VeplGuardedParser() {
			@Override
			protected TokenSource createLexer(CharStream stream) {
				throw new IllegalStateException("lexer broke");
			}
		};
		injector.injectMembers(parser);
		List<String> errors = parseErrors(parser, EVENT);
		assertEquals(1, errors.size(), errors::toString);
		assertTrue(errors.get(0).startsWith(VeplIssueCodes.UNREADABLE + ": "), errors::toString);
		assertTrue(errors.get(0).contains("lexer broke"), errors::toString);
	}
}
