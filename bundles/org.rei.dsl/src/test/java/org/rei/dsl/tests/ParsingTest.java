/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;

import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.testing.util.ParseHelper;
import org.eclipse.xtext.testing.validation.ValidationTestHelper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.rei.catalogue.ObjectType;
import org.rei.context.BuildingBlock;
import org.rei.context.Floor;
import org.rei.context.Human;
import org.rei.context.NavigationTask;
import org.rei.context.StaticObject;
import org.rei.context.TestCase;
import org.rei.context.Wall;

import com.google.inject.Inject;

@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class ParsingTest {

	private static final String BODY = """
			    object crate : Box on F_2_0 yaw -90
			    human h trajectory [F_2_1 @ 0s, F_0_1 @ 4.5 s, F_1_1 @ 6] loop
			    robot r : Waffle on F_0_0
			  }
			  mission M { tolerance 0.2 goto F_1_1 within 30s goto F_2_1 }
			}
			""";

	private static final String GRID = "testcase T {\n  room R size 3 x 2 {\n" + BODY;

	private static final String MAP = "testcase T {\n  room R map \"\n    ###\n    ...\n    ...\n  \" {\n" + BODY;

	/** The same 3 x 2 room, written out as the explicit floor graph of the metamodel. */
	private static final String EXPLICIT = """
			testcase T {
			  room R {
			    floor F_0_0 top F_0_1 right F_1_0 bottom W_0_0_bottom left W_0_0_left
			    floor F_1_0 top F_1_1 right F_2_0 bottom W_1_0_bottom left F_0_0
			    floor F_2_0 top F_2_1 right W_2_0_right bottom W_2_0_bottom left F_1_0
			    floor F_0_1 top W_0_1_top right F_1_1 bottom F_0_0 left W_0_1_left
			    floor F_1_1 top W_1_1_top right F_2_1 bottom F_1_0 left F_0_1
			    floor F_2_1 top W_2_1_top right W_2_1_right bottom F_2_0 left F_1_1
			    wall W_0_0_bottom wall W_1_0_bottom wall W_2_0_bottom wall W_2_0_right wall W_2_1_right
			    wall W_0_1_top wall W_1_1_top wall W_2_1_top wall W_0_0_left wall W_0_1_left
			""" + BODY;

	@Inject
	private ParseHelper<TestCase> parser;

	@Inject
	private ValidationTestHelper validation;

	@Test
	void gridMapAndExplicitFormsGiveTheSameFloorGraph() throws Exception {
		TestCase grid = parser.parse(GRID);
		TestCase map = parser.parse(MAP);
		TestCase explicit = parser.parse(EXPLICIT);
		validation.assertNoIssues(grid);
		validation.assertNoIssues(map);
		validation.assertNoIssues(explicit);
		assertEquals(graph(explicit), graph(grid));
		assertEquals(graph(explicit), graph(map));
		assertEquals(6, graph(grid).values().stream().filter(s -> s.startsWith("floor")).count());
		assertEquals(10, graph(grid).values().stream().filter(s -> s.equals("wall")).count());
	}

	@Test
	void referencesLinkToDerivedFloorsAndCatalogueTypes() throws Exception {
		TestCase grid = parser.parse(GRID);
		StaticObject crate = (StaticObject) grid.getOwnedEnvironment().getOwnedObjects().get(0);
		Floor f20 = floor(grid, "F_2_0");
		assertSame(f20, crate.getFloor());
		ObjectType box = crate.getType();
		assertEquals("Box", box.getName());
		assertTrue(box.eResource().getURI().toString().endsWith("default.catalogue"));
		NavigationTask first = (NavigationTask) grid.getOwnedMission().getOwnedTasks().get(0);
		assertSame(floor(grid, "F_1_1"), first.getGoal());
	}

	@Test
	void numbersDurationsAndFlagsParse() throws Exception {
		TestCase grid = parser.parse(GRID);
		StaticObject crate = (StaticObject) grid.getOwnedEnvironment().getOwnedObjects().get(0);
		assertEquals(-90.0, crate.getYaw());
		Human human = (Human) grid.getOwnedEnvironment().getOwnedObjects().get(1);
		assertTrue(human.getOwnedTrajectory().isLoop());
		assertEquals(List.of(0.0, 4.5, 6.0), human.getOwnedTrajectory().getOwnedControlPoints().stream()
				.map(p -> p.getTime()).toList());
		assertEquals(0.2, grid.getOwnedMission().getGoalTolerance());
		NavigationTask first = (NavigationTask) grid.getOwnedMission().getOwnedTasks().get(0);
		assertEquals(30.0, first.getTimeout());
		NavigationTask second = (NavigationTask) grid.getOwnedMission().getOwnedTasks().get(1);
		assertTrue(!second.isSetTimeout());
	}

	@Test
	void defaultsApplyWhenOmitted() throws Exception {
		TestCase grid = parser.parse(GRID);
		assertEquals(1.0, grid.getOwnedEnvironment().getFloorSize());
		assertEquals(120.0, grid.getOwnedMission().getTaskTimeout());
		assertEquals(null, grid.getOwnedMonitor());
	}

	@Test
	void reparsingDoesNotDuplicateDerivedFloors() throws Exception {
		TestCase grid = parser.parse(GRID);
		var resource = (org.eclipse.xtext.resource.DerivedStateAwareResource) grid.eResource();
		assertEquals(6 + 10, grid.getOwnedEnvironment().getOwnedBlocks().size());
		resource.reparse(GRID.replace("size 3 x 2", "size 4 x 2"));
		TestCase again = (TestCase) resource.getContents().get(0);
		assertEquals(8 + 12, again.getOwnedEnvironment().getOwnedBlocks().size());
		assertNotNull(floor(again, "F_3_1"));
	}

	/** Each block's name mapped to its kind and neighbours' names: comparable across syntactic forms. */
	private static Map<String, String> graph(TestCase testCase) {
		return testCase.getOwnedEnvironment().getOwnedBlocks().stream().collect(Collectors.toMap(
				BuildingBlock::getName, ParsingTest::describe, (a, b) -> a + "|" + b, TreeMap::new));
	}

	private static String describe(BuildingBlock block) {
		if (block instanceof Wall) {
			return "wall";
		}
		Floor f = (Floor) block;
		return "floor top=" + name(f.getTop()) + " right=" + name(f.getRight()) + " bottom=" + name(f.getBottom())
				+ " left=" + name(f.getLeft());
	}

	private static String name(BuildingBlock block) {
		return block == null ? "-" : block.getName();
	}

	private static Floor floor(TestCase testCase, String name) {
		return testCase.getOwnedEnvironment().getOwnedBlocks().stream().filter(b -> name.equals(b.getName()))
				.map(Floor.class::cast).findFirst().orElseThrow();
	}
}
