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

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.testing.util.ParseHelper;
import org.eclipse.xtext.testing.validation.ValidationTestHelper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.rei.catalogue.Catalogue;
import org.rei.context.Behaviour;
import org.rei.context.Crowd;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.Human;
import org.rei.context.PhysicalObject;
import org.rei.context.TestCase;
import org.rei.context.people.WalkingSpeed;
import org.rei.dsl.documentation.ReiDocumentationProvider;

import com.google.inject.Inject;

/** Crowds, groups and walking speeds: what the text says becomes the model, what it leaves out has its default. */
@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class CrowdTest {

	private static final String STATION = """
			testcase T {
			  room R size 8 x 4 {
			    crowd shoppers 4 from [F_0_0, F_0_1, F_1_0, F_1_1] to [F_7_0, F_7_1] loop scared speed 1.0 to 1.4 rate 2
			    group family 3 : Human route [F_3_2, F_6_2 wait 2s] start 1 speed 0.9
			    human ann route [F_5_3] speed 1.1 to 1.3
			    crowd few 1 from [F_2_3] to [F_6_3]
			    robot r : Waffle on F_4_0
			  }
			  mission M { goto F_4_1 goto F_5_1 }
			}
			""";

	@Inject
	private ParseHelper<TestCase> parser;

	@Inject
	private ValidationTestHelper validation;

	@Inject
	private ReiFiles files;

	@Test
	void aCrowdsOptionsComeInAnyOrder() throws Exception {
		TestCase testCase = parser.parse(STATION);
		validation.assertNoIssues(testCase);
		Crowd shoppers = (Crowd) object(testCase, 0);
		assertEquals("shoppers", shoppers.getName());
		assertEquals(4, shoppers.getCount());
		assertEquals(List.of("F_0_0", "F_0_1", "F_1_0", "F_1_1"), names(shoppers.getFrom()));
		assertEquals(List.of("F_7_0", "F_7_1"), names(shoppers.getTo()));
		assertEquals(2.0, shoppers.getRate());
		assertEquals(new WalkingSpeed(1.0, 1.4), WalkingSpeed.of(shoppers));
		assertTrue(shoppers.isLoop());
		assertEquals(Behaviour.SCARED, shoppers.getBehaviour());
		assertNull(shoppers.getFloor());
		assertNull(shoppers.startFloor(), "a crowd stands on several floors, on none of their centres");
	}

	@Test
	void whatACrowdDoesNotSayHasItsDefault() throws Exception {
		Crowd few = (Crowd) object(parser.parse(STATION), 3);
		assertFalse(few.isSetRate(), "no rate: everyone sets off at the start");
		assertFalse(few.isSetSpeed());
		assertEquals(new WalkingSpeed(1.2, null), WalkingSpeed.of(few));
		assertEquals(0.0, few.getStart());
		assertFalse(few.isLoop());
		assertEquals(Behaviour.AVOIDS, few.getBehaviour());
		assertNull(few.getType(), "the default Human, as for a human");
		assertNull(few.getQueue(), "no queue on the way");
	}

	@Test
	void aQueueIsAFloorOnTheWayAndAPace() throws Exception {
		TestCase testCase = parser.parse(STATION.replace("to [F_6_3]", "to [F_6_3] queue F_4_3 every 2.5s"));
		validation.assertNoIssues(testCase);
		Crowd few = (Crowd) object(testCase, 3);
		assertEquals("F_4_3", few.getQueue().getName());
		assertEquals(2.5, few.getQueueEvery());
		assertTrue(new ReiDocumentationProvider().getDocumentation(few).endsWith("""
				- to F_6_3
				- queueing at F_4_3 on the way: one passes every 2.5 s"""), "the hover says where it queues");
	}

	@Test
	void aGroupIsAHumanOnARouteWithPeopleBesideIt() throws Exception {
		TestCase testCase = parser.parse(STATION);
		Group family = (Group) object(testCase, 1);
		assertEquals(3, family.getCount());
		assertEquals("Human", family.getType().getName());
		assertEquals(List.of("F_3_2", "F_6_2"),
				family.getOwnedRoute().getOwnedStops().stream().map(s -> s.getFloor().getName()).toList());
		assertEquals(1.0, family.getOwnedRoute().getStart());
		assertEquals(new WalkingSpeed(0.9, null), WalkingSpeed.of(family.getOwnedRoute(), family.getType()));
		assertSame(family.getOwnedRoute().getOwnedStops().get(0).getFloor(), family.startFloor(),
				"its leader stands on the first stop, as a routed human does");
		Human ann = (Human) object(testCase, 2);
		assertEquals(new WalkingSpeed(1.1, 1.3), WalkingSpeed.of(ann.getOwnedRoute(), ann.getType()));
	}

	/** docs/language.md: the new words stay usable as names, as the route's are. */
	@Test
	void crowdGroupAndFromAreStillNames() throws Exception {
		TestCase testCase = parser.parse("""
				testcase crowd {
				  room group {
				    floor crowd right group
				    floor group right from
				    floor from right to2
				    floor to2
				    robot r : Waffle on crowd
				    crowd from2 1 from [group] to [from]
				  }
				  mission group { goto from goto to2 }
				}
				""");
		validation.assertNoIssues(testCase);
		Crowd crowd = (Crowd) object(testCase, 0);
		assertEquals(List.of("group"), names(crowd.getFrom()));
		assertEquals(List.of("from"), names(crowd.getTo()));
	}

	@Test
	void theHoverSaysWhoTheCrowdIsWhereItGoesAndHowFast() throws Exception {
		TestCase testCase = parser.parse(STATION);
		ReiDocumentationProvider hover = new ReiDocumentationProvider();
		assertEquals("""
				**Crowd shoppers**, 4 people (shoppers_1 to shoppers_4) walking at 1-1.4 m/s, setting off 2 a second \
				from 0 s, back and forth; scared: keeps a wide berth around the robot:
				- from F_0_0, F_0_1, F_1_0, F_1_1
				- to F_7_0, F_7_1""", hover.getDocumentation(object(testCase, 0)));
		assertEquals("""
				**Crowd few**, 1 person (few_1) walking at 1.2 m/s, setting off at 0 s, then staying; avoids: steps \
				around the robot and other people:
				- from F_2_3
				- to F_6_3""", hover.getDocumentation(object(testCase, 3)));
		String family = hover.getDocumentation(object(testCase, 1));
		assertTrue(family.startsWith("**Group family**, 3 people (family_1 leads, family_2 and family_3 keep near "
				+ "it), walking a route at 0.9 m/s from 1 s, then staying at the last stop; avoids: "), family);
		assertTrue(hover.getDocumentation(object(testCase, 2)).startsWith("**Human ann**, walking a route at "
				+ "1.1-1.3 m/s"));
	}

	/**
	 * A human type may say how fast its people walk: they walk so unless their own statement gives a speed, and
	 * the default Human says nothing (1.2 m/s).
	 */
	@Test
	void aTypesWalkingSpeedIsWhatItsPeopleWalkAtUnlessTheySayOtherwise(@TempDir Path dir) throws IOException {
		Path catalogue = dir.resolve("walkers.rei");
		Files.writeString(catalogue, """
				catalogue Walkers {
				  type Adult : human cylinder 0.5 x 0.5 x 1.7 mass 70 speed 1.0 to 1.4
				  type Runner : human cylinder 0.5 x 0.5 x 1.8 mass 75 speed 2.5
				}
				""");
		Path file = dir.resolve("case.rei");
		Files.writeString(file, """
				import "walkers.rei"
				testcase T {
				  room R size 8 x 4 {
				    crowd adults 2 : Adult from [F_0_0, F_0_1] to [F_7_0]
				    crowd quick 1 : Adult from [F_0_3] to [F_7_3] speed 1.3
				    group runners 2 : Runner route [F_3_2, F_6_2]
				    human bob route [F_5_3]
				    robot r : Waffle on F_4_0
				  }
				  mission M { goto F_4_1 goto F_5_1 }
				}
				""");
		assertEquals(List.of(), files.validate(catalogue));
		assertEquals(List.of(), files.validate(file));
		TestCase testCase = files.testCase(file);
		assertEquals(new WalkingSpeed(1.0, 1.4), WalkingSpeed.of((Crowd) object(testCase, 0)));
		assertEquals(new WalkingSpeed(1.3, null), WalkingSpeed.of((Crowd) object(testCase, 1)));
		Group runners = (Group) object(testCase, 2);
		assertEquals(new WalkingSpeed(2.5, null), WalkingSpeed.of(runners.getOwnedRoute(), runners.getType()));
		Human bob = (Human) object(testCase, 3);
		assertEquals(new WalkingSpeed(1.2, null), WalkingSpeed.of(bob.getOwnedRoute(), bob.getType()));
		Catalogue walkers = (Catalogue) files.load(catalogue).getContents().get(0);
		assertTrue(new ReiDocumentationProvider().getDocumentation(walkers.getOwnedTypes().get(0))
				.endsWith("70 kg; walks at 1-1.4 m/s"));
	}

	private static PhysicalObject object(TestCase testCase, int index) {
		return testCase.getOwnedEnvironment().getOwnedObjects().get(index);
	}

	private static List<String> names(List<Floor> floors) {
		return floors.stream().map(Floor::getName).toList();
	}
}
