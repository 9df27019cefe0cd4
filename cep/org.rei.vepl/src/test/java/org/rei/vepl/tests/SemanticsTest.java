/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rei.vepl.compiler.VeplLoader;

/**
 * Every operator and both contexts on a trace where the pattern must fire and one where it must not. Traces are
 * {@code "MS:EVENT EVENT ..."} steps: {@code +a} FOUND of query a, {@code -a} LOST, {@code !BEGIN} a mission event,
 * {@code /r2} another subject; {@code MS:} alone only advances the clock. Signals read {@code S@MS:object}.
 */
class SemanticsTest {

	private static final String DECLARATIONS = """
			queryEvent a() as a found
			queryEvent na() as a lost
			queryEvent b() as b found
			queryEvent c() as c found
			queryEvent d() as d found
			atomicEvent begin() as mission BEGIN
			signal S utility -1.5
			""";

	static List<String> run(String expression, String context, String trace) throws VeplLoader.VeplException {
		String vepl = DECLARATIONS + "complexEvent p() {\n  as " + expression + "\n  context " + context
				+ "\n}\nrule \"p\" on p emits S\n";
		try (Cep cep = new Cep(vepl)) {
			play(cep, trace);
			return cep.signals();
		}
	}

	static void play(Cep cep, String trace) {
		for (String step : trace.trim().split("\\s+(?=\\d+:)")) {
			String[] parts = step.split(":", 2);
			String events = parts[1].trim();
			cep.at(Long.parseLong(parts[0]), events.isEmpty() ? new String[0] : events.split("\\s+"));
		}
	}

	private static void check(String expression, String context, String trace, String... expected)
			throws VeplLoader.VeplException {
		assertEquals(List.of(expected), run(expression, context, trace), expression + " " + context + " on " + trace);
	}

	private static void both(String expression, String trace, String... expected) throws VeplLoader.VeplException {
		check(expression, "immediate", trace, expected);
		check(expression, "chronicle", trace, expected);
	}

	@Test
	void followedByFiresInOrderOnly() throws Exception {
		both("a -> b", "0:+a 10:+b", "S@10:b");
		both("a -> b", "0:+b 10:+a");
	}

	@Test
	void followedByAcceptsEventsOfOneMessageInAnyOrder() throws Exception {
		both("na -> b", "0:+b -a", "S@0:b");
	}

	@Test
	void eventsOfAMatchHaveOneSubject() throws Exception {
		both("a -> b", "0:+a/r1 5:+b/r2");
		both("a -> b", "0:+a/r1 5:+b/r1", "S@5:b");
	}

	@Test
	void windowIsClosedAndExactToTheMillisecond() throws Exception {
		both("(a -> b)[1000]", "0:+a 999:+b", "S@999:b");
		both("(a -> b)[1000]", "0:+a 1000:+b", "S@1000:b");
		both("(a -> b)[1000]", "0:+a 1001:+b");
	}

	@Test
	void orFiresOnEitherSide() throws Exception {
		both("a OR (b -> c)", "0:+b 5:+c", "S@5:c");
		both("a OR (b -> c)", "0:+c 5:+b");
	}

	@Test
	void andFiresInEitherOrderWithinTheWindow() throws Exception {
		both("(a AND b)[1000]", "0:+b 500:+a", "S@500:a");
		both("(a AND b)[1000]", "0:+b 1001:+a");
		both("(a AND b)[1000]", "0:+a 500:+a");
	}

	@Test
	void negationBetweenTwoEvents() throws Exception {
		both("a -> NOT c -> b", "0:+a 5:+b", "S@5:b");
		both("a -> NOT c -> b", "0:+a 3:+c 5:+b");
	}

	@Test
	void trailingNegationFiresWhenTheWindowHasPassed() throws Exception {
		both("(a -> NOT c)[1000]", "0:+a 1000: 1001:", "S@1001:a");
		both("(a -> NOT c)[1000]", "0:+a 999: 1000:+c 1001: 3000:");
	}

	@Test
	void leadingNegationLooksBackOverTheWindow() throws Exception {
		both("(NOT c -> b)[1000]", "0:+c 1001:+b", "S@1001:b");
		both("(NOT c -> b)[1000]", "0:+c 1000:+b");
	}

	@Test
	void countedMultiplicityNeedsThatManyOccurrences() throws Exception {
		both("a{3}", "0:+a 1:+a 2:+a", "S@2:a");
		both("a{3}", "0:+a 1:+a");
		both("(a{3})[1000]", "0:+a 500:+a 1000:+a", "S@1000:a");
		both("(a{3})[1000]", "0:+a 500:+a 1001:+a");
	}

	@Test
	void atLeastOnceAllowsRepetitionsInsideAnImmediateSequence() throws Exception {
		check("a -> b{+} -> c", "immediate", "0:+a 1:+b 2:+b 3:+c", "S@3:c");
		check("a -> b{+} -> c", "immediate", "0:+a 3:+c");
		// without {+} the second b interrupts an immediate match, not a chronicle one
		check("a -> b -> c", "immediate", "0:+a 1:+b 2:+b 3:+c");
		check("a -> b -> c", "chronicle", "0:+a 1:+b 2:+b 3:+c", "S@3:c");
	}

	@Test
	void anyNumberIsOptional() throws Exception {
		both("a -> b{*} -> c", "0:+a 1:+b 2:+b 3:+c", "S@3:c");
		both("a -> b{*} -> c", "0:+a 3:+c", "S@3:c");
		both("a -> b{*} -> c", "0:+c 3:+a");
	}

	@Test
	void immediateTakesTheLatestInitiatorAndDropsOlderOnes() throws Exception {
		check("(a -> b)[1000]", "immediate", "0:+a 10:+a 20:+b 30:+b", "S@20:b");
		check("(a -> b)[1000]", "chronicle", "0:+a 10:+a 20:+b 30:+b", "S@20:b", "S@30:b");
	}

	@Test
	void chronicleTakesTheOldestInitiatorSoLaterOnesStillFit() throws Exception {
		check("(a -> b)[1000]", "chronicle", "0:+a 900:+a 950:+b 1500:+b", "S@950:b", "S@1500:b");
		check("(a -> b)[1000]", "immediate", "0:+a 900:+a 950:+b 1500:+b", "S@950:b");
	}

	@Test
	void immediateIgnoresEventsThePatternDoesNotName() throws Exception {
		check("a -> b", "immediate", "0:+a 5:+c 10:+b", "S@10:b");
		check("a -> b", "immediate", "0:+a 5:+a 10:+b", "S@10:b");
	}

	@Test
	void eachEventIsUsedOncePerMatch() throws Exception {
		both("a -> b", "0:+a 5:+b 6:+b", "S@5:b");
		both("a", "0:+a 5:+a", "S@0:a", "S@5:a");
	}

	@Test
	void missionEventsAreAtomicEvents() throws Exception {
		both("begin -> b", "0:!BEGIN 5:+b", "S@5:b");
		both("begin -> b", "0:!END 5:+b");
	}

	@Test
	void complexEventsComposeByName() throws Exception {
		String vepl = DECLARATIONS + """
				complexEvent ab() { as a -> b }
				complexEvent abc() { as (ab -> c)[100] context immediate }
				rule "abc" on abc emits S
				""";
		try (Cep cep = new Cep(vepl)) {
			play(cep, "0:+a 50:+b 100:+c 200:+a 250:+b 301:+c");
			assertEquals(List.of("S@100:c"), cep.signals());
		}
	}

	@Test
	void filesDoNotTakeEachOthersEventsButRulesOfOneFileDo() throws Exception {
		String one = DECLARATIONS + """
				complexEvent ab() { as a -> b }
				complexEvent ac() { as a -> c }
				rule "ab" on ab emits S
				rule "ac" on ac emits S
				""";
		String other = """
				complexEvent ac2() { as a -> c }
				rule "ac2" on ac2 emits S
				""";
		try (Cep cep = new Cep(List.of(new VeplLoader.Source("one.vepl", one),
				new VeplLoader.Source("other.vepl", other)))) {
			play(cep, "0:+a 5:+b 6:+c");
			assertEquals(List.of("S@5:b", "S@6:c"), cep.signals());
		}
	}
}
