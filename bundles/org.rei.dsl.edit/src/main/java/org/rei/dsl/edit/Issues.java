/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.rei.context.Crowd;
import org.rei.context.DynamicObject;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.Human;
import org.rei.context.Mission;
import org.rei.context.MonitorSpec;
import org.rei.context.NamedElement;
import org.rei.context.NavigationTask;
import org.rei.context.PhysicalObject;
import org.rei.context.Robot;
import org.rei.context.StaticObject;
import org.rei.context.TestCase;
import org.rei.context.Wall;
import org.rei.dsl.validation.ReiIssueCodes;

/** Runs the language's own validators and says which diagram element each finding is on. */
final class Issues {

	private Issues() {
	}

	static List<ValidationIssue> of(XtextResource resource) {
		IResourceValidator validator = resource.getResourceServiceProvider().getResourceValidator();
		List<ValidationIssue> result = new ArrayList<>();
		for (Issue issue : validator.validate(resource, CheckMode.ALL, CancelIndicator.NullImpl)) {
			EObject element = issue.getUriToProblem() == null ? null
					: resource.getEObject(issue.getUriToProblem().fragment());
			Target target = target(element);
			result.add(new ValidationIssue(issue.getSeverity().name().toLowerCase(), issue.getMessage(),
					orOne(issue.getLineNumber()), orOne(issue.getColumn()), orZero(issue.getOffset()),
					orZero(issue.getLength()), issue.getCode(), target.name(), target.kind(), target.index(),
					related(issue.getCode(), element)));
		}
		return result;
	}

	/** The other elements a finding is about: the objects that share a floor with the one it is reported on. */
	private static List<String> related(String code, EObject element) {
		if (!ReiIssueCodes.FLOOR_OCCUPIED.equals(code)) {
			return List.of();
		}
		PhysicalObject object = EcoreUtil2.getContainerOfType(element, PhysicalObject.class);
		Environment environment = object == null ? null : EcoreUtil2.getContainerOfType(object, Environment.class);
		Floor floor = object == null ? null : object.startFloor();
		if (environment == null || floor == null || floor.eIsProxy()) {
			return List.of();
		}
		List<PhysicalObject> candidates = new ArrayList<>(environment.getOwnedObjects());
		if (environment.getOwnedRobot() != null) {
			candidates.add(environment.getOwnedRobot());
		}
		List<String> others = new ArrayList<>();
		for (PhysicalObject other : candidates) {
			if (other != object && other.startFloor() == floor && other.getName() != null) {
				others.add(other.getName());
			}
		}
		return others;
	}

	private record Target(String name, String kind, Integer index) {
	}

	/** The nearest enclosing element the diagram draws: a control point's human, a goal's floor and place. */
	private static Target target(EObject element) {
		for (EObject e = element; e != null; e = e.eContainer()) {
			if (e instanceof NavigationTask task && task.eContainer() instanceof Mission mission) {
				Floor goal = task.getGoal();
				return new Target(goal == null || goal.eIsProxy() ? null : goal.getName(), "goal",
						mission.getOwnedTasks().indexOf(task));
			}
			String kind = kind(e);
			if (kind != null) {
				return new Target(e instanceof NamedElement named ? named.getName() : null, kind, null);
			}
		}
		return new Target(null, null, null);
	}

	private static String kind(EObject e) {
		if (e instanceof Floor) {
			return "floor";
		} else if (e instanceof Wall) {
			return "wall";
		} else if (e instanceof Crowd) {
			return "crowd";
		} else if (e instanceof Group) {
			return "group";
		} else if (e instanceof Human) {
			return "human";
		} else if (e instanceof DynamicObject) {
			return "dynamic";
		} else if (e instanceof StaticObject) {
			return "object";
		} else if (e instanceof Robot) {
			return "robot";
		} else if (e instanceof Environment) {
			return "room";
		} else if (e instanceof Mission) {
			return "mission";
		} else if (e instanceof MonitorSpec) {
			return "monitor";
		} else if (e instanceof TestCase) {
			return "testcase";
		}
		return null;
	}

	private static int orOne(Integer value) {
		return value == null || value < 1 ? 1 : value;
	}

	private static int orZero(Integer value) {
		return value == null || value < 0 ? 0 : value;
	}
}
