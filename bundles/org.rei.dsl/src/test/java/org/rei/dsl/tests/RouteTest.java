/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.testing.util.ParseHelper;
import org.eclipse.xtext.testing.validation.ValidationTestHelper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.rei.context.Behaviour;
import org.rei.context.Human;
import org.rei.context.Route;
import org.rei.context.RouteStop;
import org.rei.context.TestCase;
import org.rei.dsl.documentation.ReiDocumentationProvider;

import com.google.inject.Inject;

/** The second form of a human: a person who walks a route of floors and sees the robot. */
@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class RouteTest {

	private static final String CROSSING = """
			testcase T {
			  room R size 6 x 3 {
			    human ann route [F_0_2, F_3_2 wait 3s, F_5_2] scared start 5 s loop speed 1.4
			    human bob : Human route [F_1_0]
			    human carl trajectory [F_2_1 @ 0s, F_4_1 @ 4s]
			    robot r : Waffle on F_0_0
			  }
			  mission M { goto F_5_0 goto F_5_1 }
			}
			""";

	@Inject
	private ParseHelper<TestCase> parser;

	@Inject
	private ValidationTestHelper validation;

	@Test
	void theOptionsComeInAnyOrder() throws Exception {
		TestCase testCase = parser.parse(CROSSING);
		validation.assertNoIssues(testCase);
		Human ann = human(testCase, 0);
		Route route = ann.getOwnedRoute();
		assertNull(ann.getOwnedTrajectory());
		assertEquals(List.of("F_0_2", "F_3_2", "F_5_2"),
				route.getOwnedStops().stream().map(s -> s.getFloor().getName()).toList());
		assertEquals(List.of(0.0, 3.0, 0.0), route.getOwnedStops().stream().map(RouteStop::getWait).toList());
		assertEquals(1.4, route.getSpeed());
		assertEquals(5.0, route.getStart());
		assertTrue(route.isLoop());
		assertEquals(Behaviour.SCARED, route.getBehaviour());
		assertSame(route.getOwnedStops().get(0).getFloor(), ann.startFloor());
	}

	@Test
	void whatIsNotWrittenHasItsDefault() throws Exception {
		Human bob = human(parser.parse(CROSSING), 1);
		Route route = bob.getOwnedRoute();
		assertEquals(1, route.getOwnedStops().size());
		assertEquals(1.2, route.getSpeed());
		assertEquals(0.0, route.getStart());
		assertFalse(route.isLoop());
		assertEquals(Behaviour.AVOIDS, route.getBehaviour());
		assertEquals("F_1_0", bob.startFloor().getName());
	}

	@Test
	void aTrajectoryHumanIsAsBefore() throws Exception {
		Human carl = human(parser.parse(CROSSING), 2);
		assertNull(carl.getOwnedRoute());
		assertEquals(2, carl.getOwnedTrajectory().getOwnedControlPoints().size());
		assertEquals("F_2_1", carl.startFloor().getName());
	}

	/** docs/language.md: the words of a route stay usable as names, as speed and the others are. */
	@Test
	void theRoutesWordsAreStillNames() throws Exception {
		TestCase testCase = parser.parse("""
				testcase route {
				  room wait {
				    floor route right wait
				    floor wait right start
				    floor start right avoids
				    floor avoids right ignores
				    floor ignores right curious
				    floor curious right scared
				    floor scared right blocks
				    floor blocks
				    robot start2 : Waffle on route
				    human blocks2 route [wait wait 1s, start, scared] ignores start 2 once
				  }
				  mission speed { goto curious goto blocks }
				}
				""");
		validation.assertNoIssues(testCase);
		Human human = human(testCase, 0);
		assertEquals(List.of("wait", "start", "scared"),
				human.getOwnedRoute().getOwnedStops().stream().map(s -> s.getFloor().getName()).toList());
		assertEquals(1.0, human.getOwnedRoute().getOwnedStops().get(0).getWait());
		assertEquals(Behaviour.IGNORES, human.getOwnedRoute().getBehaviour());
		assertEquals(2.0, human.getOwnedRoute().getStart());
	}

	@Test
	void theHoverSaysWhereThePersonGoesAndHowItBehaves() throws Exception {
		String hover = new ReiDocumentationProvider().getDocumentation(human(parser.parse(CROSSING), 0));
		assertEquals("""
				**Human ann**, walking a route at 1.4 m/s from 5 s in a loop; scared: keeps a wide berth around the \
				robot:
				- F_0_2: x 0..1 m, y 2..3 m, centre (0.50, 2.50)
				- F_3_2, waits 3 s: x 3..4 m, y 2..3 m, centre (3.50, 2.50)
				- F_5_2: x 5..6 m, y 2..3 m, centre (5.50, 2.50)""", hover);
		String bob = new ReiDocumentationProvider().getDocumentation(human(parser.parse(CROSSING), 1));
		assertTrue(bob.startsWith("**Human bob**, walking a route at 1.2 m/s, then staying at the last stop; "
				+ "avoids: steps around the robot and other people:\n- F_1_0: "), bob);
	}

	private static Human human(TestCase testCase, int index) {
		return (Human) testCase.getOwnedEnvironment().getOwnedObjects().stream().filter(Human.class::isInstance)
				.toList().get(index);
	}
}
