/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * Property over random traces (thesis 7.4.7 reported many more FAR->CLOSE than CLOSE->FAR): with the default
 * patterns, entries into and exits from each zone alternate and their counts differ by at most one at the end -
 * for geometry and laser, two robots interleaved, jumps over CLOSE, LOST/FOUND of one message in random order,
 * steps of 1 ms to 1.5 s so that several changes fall inside one 1000 ms window.
 */
class ZoneBalanceTest {

	private static final String[] GEOMETRY = { "robotFar", "robotClose", "robotInCollision" };
	private static final String[] LASER = { "laserSensesNothingClose", "laserSensesCloseness", "laserSensesCollision" };

	@Test
	void entriesAndExitsOfEveryZoneAlternate() throws Exception {
		Random random = new Random(7_4_7);
		for (int trace = 0; trace < 40; trace++) {
			try (Cep cep = new Cep(DefaultPatterns.sources())) {
				int[][] state = new int[2][2]; // [robot][geometry, laser]: 0 FAR, 1 CLOSE, 2 COLLISION
				List<List<String>> expected = List.of(new ArrayList<>(), new ArrayList<>());
				long t = 0;
				for (int step = 0; step < 150; step++) {
					t += 1 + random.nextInt(random.nextBoolean() ? 200 : 1500);
					List<String> events = new ArrayList<>();
					for (int robot = 0; robot < 2; robot++) {
						for (int family = 0; family < 2; family++) {
							int from = state[robot][family];
							int to = random.nextInt(3);
							if (to == from || random.nextInt(3) == 0) {
								continue;
							}
							String[] q = family == 0 ? GEOMETRY : LASER;
							events.add("-" + q[from] + "/r" + robot);
							events.add("+" + q[to] + "/r" + robot);
							state[robot][family] = to;
							expected.get(robot).addAll(transitions(family == 0 ? "GEOM" : "LASER", from, to));
						}
					}
					Collections.shuffle(events, random);
					cep.at(t, events.toArray(String[]::new));
				}
				for (int robot = 0; robot < 2; robot++) {
					assertAlternate(namesOf(cep, "r" + robot), "GEOM");
					assertAlternate(namesOf(cep, "r" + robot), "LASER");
				}
				assertEquals(expected.get(0).size() + expected.get(1).size(), cep.signals().size());
				// each family's signals in the order of its changes; between the families, changes at the same time
				// come in the rule engine's order, which depends on every rule loaded (the fault patterns changed it)
				for (int robot = 0; robot < 2; robot++) {
					for (String family : new String[] { "GEOM", "LASER" }) {
						assertEquals(ofFamily(expected.get(robot), family), ofFamily(namesOf(cep, "r" + robot), family),
								"trace " + trace + ", r" + robot + ", " + family);
					}
				}
			}
		}
	}

	private static List<String> ofFamily(List<String> signals, String family) {
		return signals.stream().filter(s -> s.startsWith("SIG_" + family + "_")).toList();
	}

	private static List<String> namesOf(Cep cep, String robot) {
		return cep.sink.bySubject(robot);
	}

	/** The signals a change of state must give: a jump passes through CLOSE. */
	private static List<String> transitions(String family, int from, int to) {
		String[] names = { "FAR", "CLOSE", "COLLISION" };
		List<String> out = new ArrayList<>();
		int step = to > from ? 1 : -1;
		for (int s = from; s != to; s += step) {
			out.add("SIG_" + family + "_" + names[s] + "_TRANSIT_" + names[s + step]);
		}
		return out;
	}

	private static void assertAlternate(List<String> signals, String family) {
		int danger = 0;
		int collision = 0;
		int enterDanger = 0;
		int exitDanger = 0;
		for (String s : signals) {
			if (!s.startsWith("SIG_" + family + "_")) {
				continue;
			}
			if (s.endsWith("FAR_TRANSIT_CLOSE")) {
				danger++;
				enterDanger++;
			} else if (s.endsWith("CLOSE_TRANSIT_FAR")) {
				danger--;
				exitDanger++;
			} else if (s.endsWith("CLOSE_TRANSIT_COLLISION")) {
				collision++;
			} else if (s.endsWith("COLLISION_TRANSIT_CLOSE")) {
				collision--;
			}
			assertTrue(danger == 0 || danger == 1, "danger zone entered twice or left twice: " + signals);
			assertTrue(collision == 0 || collision == 1, "collision zone entered twice or left twice: " + signals);
			assertTrue(collision <= danger, "collision outside the danger zone: " + signals);
		}
		assertTrue(Math.abs(enterDanger - exitDanger) <= 1, signals.toString());
	}
}
