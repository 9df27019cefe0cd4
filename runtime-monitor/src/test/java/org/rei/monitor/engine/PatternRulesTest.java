/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.vepl.compiler.VeplLoader;

/** The rules compiled at start from the packaged patterns are the ones the build compiled ahead of time. */
class PatternRulesTest {

	private static Map<String, String> byName(List<DrlSources.Source> sources) {
		Map<String, String> out = new TreeMap<>();
		for (DrlSources.Source s : sources) {
			out.put(Path.of(s.path()).getFileName().toString(), s.text());
		}
		return out;
	}

	@Test
	void compilingAtStartGivesTheDrlTheBuildGenerated() throws Exception {
		List<DrlSources.Source> atStart = PatternRules.compile(PatternRules.packaged(),
				DrlSources.packaged(DrlSources.QUERIES));
		Map<String, String> aheadOfTime = byName(DrlSources.packaged(DrlSources.RULES));
		assertEquals(List.of("contacts.drl", "faults.drl", "geometry.drl", "laser.drl", "mission.drl", "vepl-events.drl"),
				List.copyOf(aheadOfTime.keySet()));
		assertEquals(aheadOfTime, byName(atStart));
	}

	@Test
	void userPatternsAreAddedToTheDefaultsAndCompiledWithoutRebuilding(@TempDir Path dir) throws Exception {
		Files.writeString(dir.resolve("mine.vepl"), """
				complexEvent closeThenCollisionQuickly() {
				  as (atomicCloseToObject -> atomicCollisionToObject)[500]
				  context chronicle
				}
				signal SIG_USER_FAST_HIT utility -50
				rule "Robot hits something within half a second of coming close" on closeThenCollisionQuickly
				  emits SIG_USER_FAST_HIT
				""");
		List<DrlSources.Source> rules = PatternRules.compile(PatternRules.select(true, dir),
				DrlSources.packaged(DrlSources.QUERIES));
		assertTrue(byName(rules).get("mine.drl").contains("SIG_USER_FAST_HIT"));
		SessionFactory.build(concat(DrlSources.packaged(DrlSources.QUERIES), rules)).dispose();
	}

	@Test
	void anUnknownQueryFailsWithFileLineAndColumn(@TempDir Path dir) throws Exception {
		Files.writeString(dir.resolve("bad.vepl"), "\nqueryEvent x() as noSuchQuery found\n");
		VeplLoader.VeplException e = assertThrows(VeplLoader.VeplException.class, () -> PatternRules
				.compile(PatternRules.select(false, dir), DrlSources.packaged(DrlSources.QUERIES)));
		assertTrue(e.getMessage().contains("bad.vepl:2:19: Unknown query 'noSuchQuery'"), e.getMessage());
	}

	private static List<DrlSources.Source> concat(List<DrlSources.Source> a, List<DrlSources.Source> b) {
		List<DrlSources.Source> out = new java.util.ArrayList<>(a);
		out.addAll(b);
		return out;
	}
}
