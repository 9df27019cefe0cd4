/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.CatalogueFactory;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.Shape;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.Behaviour;
import org.rei.context.ContextFactory;
import org.rei.context.ControlPoint;
import org.rei.context.Crowd;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.Human;
import org.rei.context.Mission;
import org.rei.context.NavigationTask;
import org.rei.context.Robot;
import org.rei.context.Route;
import org.rei.context.RouteStop;
import org.rei.context.StaticObject;
import org.rei.context.TestCase;
import org.rei.context.Trajectory;
import org.rei.context.Wall;

/** Test cases built as the DSL would build them: explicit floor graph, walls all around, types partly implicit. */
final class TestCases {

	private static final ContextFactory F = ContextFactory.eINSTANCE;
	static final Catalogue CATALOGUE = Catalogues.loadDefault(new ResourceSetImpl());

	private TestCases() {
	}

	/** Floors F_x_y, each declaring its right and top neighbours, and one wall W_x_y_side per open side. */
	static Floor[][] room(Environment env, int columns, int rows) {
		Floor[][] g = new Floor[columns][rows];
		for (int x = 0; x < columns; x++) {
			for (int y = 0; y < rows; y++) {
				Floor floor = F.createFloor();
				floor.setName("F_" + x + "_" + y);
				env.getOwnedBlocks().add(floor);
				g[x][y] = floor;
			}
		}
		for (int x = 0; x < columns; x++) {
			for (int y = 0; y < rows; y++) {
				Floor f = g[x][y];
				f.setRight(x + 1 < columns ? g[x + 1][y] : wall(env, f, "right"));
				f.setTop(y + 1 < rows ? g[x][y + 1] : wall(env, f, "top"));
				if (x == 0) {
					f.setLeft(wall(env, f, "left"));
				}
				if (y == 0) {
					f.setBottom(wall(env, f, "bottom"));
				}
			}
		}
		return g;
	}

	private static Wall wall(Environment env, Floor floor, String side) {
		Wall wall = F.createWall();
		wall.setName("W" + floor.getName().substring(1) + "_" + side);
		env.getOwnedBlocks().add(wall);
		return wall;
	}

	/**
	 * 3 x 2 floors walled around, a table turned by 90 degrees on F_1_0, a human looping F_0_1 - F_2_1 - F_2_0, the
	 * robot on F_0_0 and goals F_2_1 (timeout 60) and F_0_0.
	 */
	static TestCase small() {
		TestCase testCase = F.createTestCase();
		testCase.setName("SmallRoom");
		Environment env = F.createEnvironment();
		env.setName("Lab");
		testCase.setOwnedEnvironment(env);
		Floor[][] g = room(env, 3, 2);

		StaticObject table = F.createStaticObject();
		table.setName("table1");
		table.setType(Catalogues.find(CATALOGUE, "Table").orElseThrow());
		table.setFloor(g[1][0]);
		table.setYaw(90);
		env.getOwnedObjects().add(table);

		Human human = F.createHuman();
		human.setName("h1");
		human.setFloor(g[0][1]);
		Trajectory trajectory = F.createTrajectory();
		trajectory.setLoop(true);
		trajectory.getOwnedControlPoints().add(point(g[0][1], 0));
		trajectory.getOwnedControlPoints().add(point(g[2][1], 10));
		trajectory.getOwnedControlPoints().add(point(g[2][0], 15.5));
		human.setOwnedTrajectory(trajectory);
		env.getOwnedObjects().add(human);

		Robot robot = F.createRobot();
		robot.setName("tb3");
		robot.setType(Catalogues.find(CATALOGUE, "Waffle").orElseThrow());
		robot.setFloor(g[0][0]);
		env.setOwnedRobot(robot);

		Mission mission = F.createMission();
		mission.setName("Deliver");
		NavigationTask there = F.createNavigationTask();
		there.setGoal(g[2][1]);
		there.setTimeout(60);
		NavigationTask back = F.createNavigationTask();
		back.setGoal(g[0][0]);
		mission.getOwnedTasks().add(there);
		mission.getOwnedTasks().add(back);
		testCase.setOwnedMission(mission);
		return testCase;
	}

	/**
	 * {@link #small()} with two people who see the robot after its human on rails: ann walks F_2_1, F_1_1 (where she
	 * waits 3 s), F_2_0 with every default; bob, curious, stands on F_1_1 from 5.5 s at 0.8 m/s, looping.
	 */
	static TestCase withPeople() {
		TestCase testCase = small();
		Environment env = testCase.getOwnedEnvironment();
		Floor[][] g = new Floor[3][2];
		for (var block : env.getOwnedBlocks()) {
			if (block instanceof Floor floor) {
				String[] xy = floor.getName().split("_");
				g[Integer.parseInt(xy[1])][Integer.parseInt(xy[2])] = floor;
			}
		}
		Human ann = F.createHuman();
		ann.setName("ann");
		Route walk = F.createRoute();
		walk.getOwnedStops().add(stop(g[2][1], 0));
		walk.getOwnedStops().add(stop(g[1][1], 3));
		walk.getOwnedStops().add(stop(g[2][0], 0));
		ann.setOwnedRoute(walk);
		env.getOwnedObjects().add(ann);

		Human bob = F.createHuman();
		bob.setName("bob");
		bob.setType(Catalogues.find(CATALOGUE, "Human").orElseThrow());
		Route stand = F.createRoute();
		stand.getOwnedStops().add(stop(g[1][1], 0));
		stand.setSpeed(0.8);
		stand.setStart(5.5);
		stand.setLoop(true);
		stand.setBehaviour(Behaviour.CURIOUS);
		bob.setOwnedRoute(stand);
		env.getOwnedObjects().add(bob);
		return testCase;
	}

	/**
	 * 8 x 4 floors walled around, the robot on F_4_0 with goals F_4_3 and F_4_1, and people who see it: a scared
	 * crowd of 3 ({@code crowd shoppers 3 from [F_0_1, F_0_2] to [F_7_1] rate 2 speed 1.0 to 1.4 loop scared}:
	 * F_7_1 holds one place, which all three walk to), a group of 2 ({@code group family 2 route [F_3_2, F_5_2
	 * wait 2s] start 1}) and ann, of a type Adult that walks at 0.8 to 1.0 m/s, standing on F_6_3
	 * ({@code human ann : Adult route [F_6_3]}).
	 */
	static TestCase withCrowds() {
		TestCase testCase = grid(8, 4);
		Environment env = testCase.getOwnedEnvironment();
		Floor[][] g = new Floor[8][4];
		for (var block : env.getOwnedBlocks()) {
			if (block instanceof Floor floor) {
				String[] xy = floor.getName().split("_");
				g[Integer.parseInt(xy[1])][Integer.parseInt(xy[2])] = floor;
			}
		}
		env.getOwnedRobot().setFloor(g[4][0]);
		NavigationTask back = F.createNavigationTask();
		back.setGoal(g[4][1]);
		((NavigationTask) testCase.getOwnedMission().getOwnedTasks().get(0)).setGoal(g[4][3]);
		testCase.getOwnedMission().getOwnedTasks().add(back);

		Crowd shoppers = F.createCrowd();
		shoppers.setName("shoppers");
		shoppers.setCount(3);
		shoppers.getFrom().add(g[0][1]);
		shoppers.getFrom().add(g[0][2]);
		shoppers.getTo().add(g[7][1]);
		shoppers.setRate(2);
		shoppers.setSpeed(1.0);
		shoppers.setSpeedTo(1.4);
		shoppers.setLoop(true);
		shoppers.setBehaviour(Behaviour.SCARED);
		env.getOwnedObjects().add(shoppers);

		Group family = F.createGroup();
		family.setName("family");
		family.setCount(2);
		Route walk = F.createRoute();
		walk.getOwnedStops().add(stop(g[3][2], 0));
		walk.getOwnedStops().add(stop(g[5][2], 2));
		walk.setStart(1);
		family.setOwnedRoute(walk);
		env.getOwnedObjects().add(family);

		ObjectType adult = CatalogueFactory.eINSTANCE.createObjectType();
		adult.setName("Adult");
		adult.setCategory(ObjectCategory.HUMAN);
		adult.setShape(Shape.CYLINDER);
		adult.setSizeX(0.5);
		adult.setSizeY(0.5);
		adult.setSizeZ(1.7);
		adult.setMass(70);
		adult.setColour("#E0AC69");
		adult.setWalkingSpeed(0.8);
		adult.setWalkingSpeedTo(1.0);
		Human ann = F.createHuman();
		ann.setName("ann");
		ann.setType(adult);
		Route stand = F.createRoute();
		stand.getOwnedStops().add(stop(g[6][3], 0));
		ann.setOwnedRoute(stand);
		env.getOwnedObjects().add(ann);
		return testCase;
	}

	private static RouteStop stop(Floor floor, double wait) {
		RouteStop stop = F.createRouteStop();
		stop.setFloor(floor);
		stop.setWait(wait);
		return stop;
	}

	/** columns x rows floors walled around with the robot in the corner and one goal in the far corner. */
	static TestCase grid(int columns, int rows) {
		TestCase testCase = F.createTestCase();
		testCase.setName("Grid");
		Environment env = F.createEnvironment();
		env.setName("Hall");
		testCase.setOwnedEnvironment(env);
		Floor[][] g = room(env, columns, rows);
		Robot robot = F.createRobot();
		robot.setName("tb3");
		robot.setFloor(g[0][0]);
		env.setOwnedRobot(robot);
		Mission mission = F.createMission();
		mission.setName("Cross");
		NavigationTask task = F.createNavigationTask();
		task.setGoal(g[columns - 1][rows - 1]);
		mission.getOwnedTasks().add(task);
		testCase.setOwnedMission(mission);
		return testCase;
	}

	private static ControlPoint point(Floor floor, double time) {
		ControlPoint point = F.createControlPoint();
		point.setFloor(floor);
		point.setTime(time);
		return point;
	}
}
