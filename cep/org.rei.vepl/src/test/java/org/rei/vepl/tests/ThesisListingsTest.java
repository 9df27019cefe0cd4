/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rei.vepl.compiler.VeplLoader;

/** The four listings of thesis 9.2.2 parse as printed, are the default patterns, and give Table 2's signals. */
class ThesisListingsTest {

	// thesis 9.2.2.1, with the thesis's query names (findFarObject...) bound to REI's state queries
	static final String QUERY_EVENTS = """
			queryEvent atomicFarFromObject() as robotFar found
			queryEvent notAtomicFarFromObject() as robotFar lost
			queryEvent atomicCloseToObject() as robotClose found
			queryEvent notAtomicCloseToObject() as robotClose lost
			queryEvent atomicCollisionToObject() as robotInCollision found
			queryEvent notAtomicCollisionToObject() as robotInCollision lost
			""";

	// thesis 9.2.2.2 to 9.2.2.5, character for character (including the missing space after 'as' in two of them)
	static final List<String> LISTINGS = List.of("""
			complexEvent transitionFarToClose(){
			  as (notAtomicFarFromObject -> atomicCloseToObject){+}[1000]
			  context immediate
			}""", """
			complexEvent transitionCloseToFar(){
			  as (notAtomicCloseToObject -> atomicFarFromObject){+}[1000]
			  context immediate
			}""", """
			complexEvent closeTransitCollision(){
			  as(notAtomicCloseToObject -> atomicCollisionToObject){+}[1000]
			  context immediate
			}""", """
			complexEvent collisionTransitClose(){
			  as(notAtomicCollisionToObject -> atomicCloseToObject){+}[1000]
			  context immediate
			}""");

	static final String RULES = """
			signal FAR_CLOSE
			signal CLOSE_FAR
			signal CLOSE_COLLISION
			signal COLLISION_CLOSE
			rule "far to close" on transitionFarToClose emits FAR_CLOSE
			rule "close to far" on transitionCloseToFar emits CLOSE_FAR
			rule "close to collision" on closeTransitCollision emits CLOSE_COLLISION
			rule "collision to close" on collisionTransitClose emits COLLISION_CLOSE
			""";

	@Test
	void theDefaultGeometryPatternsContainTheListingsVerbatim() throws Exception {
		String geometry = Files.readString(DefaultPatterns.folder().resolve("geometry.vepl"));
		for (String listing : LISTINGS) {
			assertTrue(geometry.contains(listing), listing);
		}
	}

	@Test
	void theListingsAloneGiveTable2sTransitions() throws Exception {
		assertGivesTable2sTransitions(QUERY_EVENTS + String.join("\n\n", LISTINGS) + "\n" + RULES);
	}

	/** Far -> close -> collision -> close -> far, one state message per change, LOST and FOUND in either order. */
	private static void assertGivesTable2sTransitions(String vepl) throws Exception {
		try (Cep cep = new Cep(vepl)) {
			cep.at(0).at(100, "-robotFar", "+robotClose").at(600, "+robotInCollision", "-robotClose")
					.at(900, "-robotInCollision", "+robotClose").at(2000, "+robotFar", "-robotClose");
			assertEquals(List.of("FAR_CLOSE@100:robotClose", "CLOSE_COLLISION@600:robotInCollision",
					"COLLISION_CLOSE@900:robotClose", "CLOSE_FAR@2000:robotFar"), cep.signals());
		}
	}

	@Test
	void theListingsAloneReproduceTheImbalanceOfThesis747() throws Exception {
		// far -> collision in one sample, then collision -> close 0.5 s later: the jump's LOST of far is still in
		// the window and pairs with the later FOUND of close - a FAR->CLOSE with no CLOSE->FAR ever to match it
		String vepl = QUERY_EVENTS + String.join("\n\n", LISTINGS) + "\n" + RULES;
		try (Cep cep = new Cep(vepl)) {
			cep.at(0).at(100, "-robotFar", "+robotInCollision").at(600, "-robotInCollision", "+robotClose");
			assertTrue(cep.signals().contains("FAR_CLOSE@600:robotClose"), cep.signals().toString());
			assertTrue(cep.signals().stream().noneMatch(x -> x.startsWith("CLOSE_COLLISION")), cep.signals().toString());
		}
		try (Cep cep = new Cep(DefaultPatterns.sources())) {
			cep.at(0).at(100, "-robotFar", "+robotInCollision").at(600, "-robotInCollision", "+robotClose");
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE@100:robotInCollision",
					"SIG_GEOM_CLOSE_TRANSIT_COLLISION@100:robotInCollision",
					"SIG_GEOM_COLLISION_TRANSIT_CLOSE@600:robotClose"), cep.signals());
		}
	}

	// thesis 9.2.2.1 as printed (the thesis's query names), under the header every VIATRA-CEP file starts with
	static final String PRELIMINARIES = """
			package org.rei.patterns

			import-queries org.rei.queries.*
			import "http://www.rei.org/runtime/1.0"

			queryEvent atomicFarFromObject() as findFarObject found
			queryEvent notAtomicFarFromObject() as findFarObject lost

			queryEvent atomicCloseToObject() as findCloseToObject found
			queryEvent notAtomicCloseToObject() as findCloseToObject lost

			queryEvent atomicCollisionToObject() as findCollisionToObject found
			queryEvent notAtomicCollisionToObject() as findCollisionToObject lost
			""";

	@Test
	void theAppendixCompilesVerbatimIncludingItsPreliminariesAndHeader() throws Exception {
		assertGivesTable2sTransitions(PRELIMINARIES + "\n" + String.join("\n\n", LISTINGS) + "\n" + RULES);
	}

	@Test
	void eventsWithoutParenthesesAsInViatraCep() throws Exception {
		String vepl = """
				atomicEvent begun as mission BEGIN
				queryEvent near as robotClose found
				complexEvent startsNear() { as (begun -> near)[1000] }
				signal STARTS_NEAR
				rule startsNear on startsNear emits STARTS_NEAR
				""";
		try (Cep cep = new Cep(vepl)) {
			cep.at(0, "!BEGIN").at(100, "-robotFar", "+robotClose");
			assertEquals(List.of("STARTS_NEAR@100:robotClose"), cep.signals());
		}
	}

	@Test
	void theDefaultPatternsCompile() throws VeplLoader.VeplException {
		try (Cep cep = new Cep(DefaultPatterns.sources())) {
			cep.at(0, "!BEGIN").at(10, "!TASK_START").at(20, "!TASK_FAIL").at(30, "!END");
			assertEquals(List.of("SIG_MISSION_BEGIN@0:mission", "SIG_MISSION_TASK_START@10:mission",
					"SIG_MISSION_TASK_FAIL@20:mission", "SIG_MISSION_END@30:mission"), cep.signals());
			assertEquals(-100.0, cep.rules.utilities().get("SIG_MISSION_TASK_FAIL"));
			assertEquals(null, cep.rules.utilities().get("SIG_LASER_FAR_TRANSIT_CLOSE"));
		}
	}
}
