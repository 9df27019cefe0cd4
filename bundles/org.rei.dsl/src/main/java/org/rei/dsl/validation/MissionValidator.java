/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.xtext.validation.Check;
import org.rei.context.BuildingBlock;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Mission;
import org.rei.context.NavigationTask;
import org.rei.context.PhysicalObject;
import org.rei.context.StaticObject;
import org.rei.context.Task;
import org.rei.context.TestCase;

/**
 * A mission has at least two goals (thesis 4.1.2: start and final place), each on a free floor the robot can
 * reach from its start through floor neighbours.
 */
public class MissionValidator extends ReiCheckBase {

	@Check
	public void checkMissionPresent(TestCase testCase) {
		if (testCase.getOwnedMission() == null) {
			error("Test case '" + testCase.getName() + "' has no mission: expected 'mission NAME { goto FLOOR goto FLOOR }'",
					testCase, ContextPackage.Literals.NAMED_ELEMENT__NAME, ReiIssueCodes.MISSING_MISSION);
		}
	}

	@Check
	public void checkAtLeastTwoGoals(Mission mission) {
		long goals = mission.getOwnedTasks().stream().filter(NavigationTask.class::isInstance).count();
		if (goals < 2) {
			error("Mission '" + mission.getName() + "' has " + goals + " goal(s): expected at least two "
					+ "(a start and a final place)", mission, ContextPackage.Literals.NAMED_ELEMENT__NAME,
					ReiIssueCodes.TOO_FEW_GOALS);
		}
	}

	@Check
	public void checkPositiveLimits(Mission mission) {
		if (!(mission.getGoalTolerance() > 0)) {
			error("Goal tolerance must be positive, in metres", mission,
					ContextPackage.Literals.MISSION__GOAL_TOLERANCE, ReiIssueCodes.NON_POSITIVE);
		}
		if (!(mission.getTaskTimeout() > 0)) {
			error("Task timeout must be positive, in seconds", mission, ContextPackage.Literals.MISSION__TASK_TIMEOUT,
					ReiIssueCodes.NON_POSITIVE);
		}
		for (Task task : mission.getOwnedTasks()) {
			if (task instanceof NavigationTask navigation && navigation.isSetTimeout() && !(navigation.getTimeout() > 0)) {
				error("Task timeout must be positive, in seconds", navigation,
						ContextPackage.Literals.NAVIGATION_TASK__TIMEOUT, ReiIssueCodes.NON_POSITIVE);
			}
		}
	}

	@Check
	public void checkGoalsReachableAndFree(TestCase testCase) {
		Mission mission = testCase.getOwnedMission();
		Environment environment = testCase.getOwnedEnvironment();
		if (mission == null || environment == null || environment.getOwnedRobot() == null) {
			return;
		}
		Floor start = environment.getOwnedRobot().getFloor();
		if (start == null || start.eIsProxy()) {
			return;
		}
		Set<Floor> reachable = reachableFrom(start, environment);
		Map<Floor, PhysicalObject> furniture = new HashMap<>();
		for (PhysicalObject object : environment.getOwnedObjects()) {
			if (object instanceof StaticObject && object.getFloor() != null) {
				furniture.putIfAbsent(object.getFloor(), object);
			}
		}
		for (Task task : mission.getOwnedTasks()) {
			if (!(task instanceof NavigationTask navigation) || navigation.getGoal() == null
					|| navigation.getGoal().eIsProxy()) {
				continue;
			}
			Floor goal = navigation.getGoal();
			if (!reachable.contains(goal)) {
				error("Goal " + goal.getName() + " cannot be reached from the robot's floor " + start.getName()
						+ " through neighbouring floors", navigation, ContextPackage.Literals.NAVIGATION_TASK__GOAL,
						ReiIssueCodes.GOAL_UNREACHABLE);
			} else if (furniture.containsKey(goal)) {
				error("Goal " + goal.getName() + " is occupied by '" + furniture.get(goal).getName()
						+ "': expected a free floor", navigation, ContextPackage.Literals.NAVIGATION_TASK__GOAL,
						ReiIssueCodes.GOAL_OCCUPIED);
			}
		}
	}

	/** Floors connected to the start floor; a neighbour reference links two floors both ways. */
	static Set<Floor> reachableFrom(Floor start, Environment environment) {
		Map<Floor, List<Floor>> adjacency = new HashMap<>();
		for (BuildingBlock block : environment.getOwnedBlocks()) {
			if (block instanceof Floor floor) {
				for (BuildingBlock neighbour : new BuildingBlock[] { floor.getTop(), floor.getRight(),
						floor.getBottom(), floor.getLeft() }) {
					if (neighbour instanceof Floor other && !other.eIsProxy()) {
						adjacency.computeIfAbsent(floor, f -> new ArrayList<>()).add(other);
						adjacency.computeIfAbsent(other, f -> new ArrayList<>()).add(floor);
					}
				}
			}
		}
		Set<Floor> seen = new HashSet<>(List.of(start));
		ArrayDeque<Floor> queue = new ArrayDeque<>(seen);
		while (!queue.isEmpty()) {
			for (Floor next : adjacency.getOrDefault(queue.poll(), List.of())) {
				if (seen.add(next)) {
					queue.add(next);
				}
			}
		}
		return seen;
	}
}
