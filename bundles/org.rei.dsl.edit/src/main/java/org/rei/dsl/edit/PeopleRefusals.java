/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.util.List;

import org.rei.context.Crowd;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.PhysicalObject;
import org.rei.context.TestCase;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.RemoveFloor;
import org.rei.dsl.edit.EditOperation.RotateObject;
import org.rei.dsl.edit.EditOperation.SetRoute;
import org.rei.dsl.edit.EditOperation.SetTrajectory;

/**
 * What only the text says of a crowd or a group (docs/language.md, "Crowds and groups"): as many people as its line
 * says, placed by the generator, so the diagram draws a crowd's areas and a group's route but never drags them as
 * one body (a crowd's areas change through setCrowd). Operations on one are refused before the model is touched,
 * with a message that says so; deleting one deletes its line, as for any person. A floor a
 * crowd names cannot be removed (a group's stops are route stops, which {@link ModelEditor} already guards).
 */
final class PeopleRefusals {

	private PeopleRefusals() {
	}

	/** @throws EditRefusedException for the first operation that would change a crowd or a group */
	static void check(TestCase testCase, List<EditOperation> operations) {
		Environment environment = testCase.getOwnedEnvironment();
		if (environment == null) {
			return;
		}
		for (EditOperation operation : operations) {
			if (operation instanceof MoveObject move) {
				refuse(environment, move.name(), "moved");
			} else if (operation instanceof RotateObject rotate) {
				refuse(environment, rotate.name(), "turned");
			} else if (operation instanceof SetTrajectory set) {
				refuse(environment, set.name(), "given a trajectory");
			} else if (operation instanceof SetRoute set) {
				refuse(environment, set.name(), "re-routed");
			} else if (operation instanceof RemoveFloor remove) {
				refuseRemoval(environment, remove.name());
			}
		}
	}

	private static void refuse(Environment environment, String name, String what) {
		for (PhysicalObject object : environment.getOwnedObjects()) {
			if (object.getName() == null || !object.getName().equals(name)) {
				continue;
			}
			if (object instanceof Crowd crowd) {
				throw new EditRefusedException("'" + name + "' is a crowd of " + crowd.getCount() + " and cannot be "
						+ what + " in the diagram: change its line in the text");
			}
			if (object instanceof Group group) {
				throw new EditRefusedException("'" + name + "' is a group of " + group.getCount() + " and cannot be "
						+ what + " in the diagram: change its line in the text");
			}
			return;
		}
	}

	private static void refuseRemoval(Environment environment, String floor) {
		for (PhysicalObject object : environment.getOwnedObjects()) {
			if (object instanceof Crowd crowd && (names(crowd.getFrom(), floor) || names(crowd.getTo(), floor))) {
				throw new EditRefusedException("Floor " + floor + " is still used by crowd '" + crowd.getName()
						+ "': change its line in the text first");
			}
		}
	}

	private static boolean names(List<Floor> floors, String name) {
		return floors.stream().anyMatch(f -> !f.eIsProxy() && name.equals(f.getName()));
	}
}
