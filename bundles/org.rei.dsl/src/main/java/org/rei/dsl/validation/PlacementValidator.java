/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.validation.Check;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.RobotType;
import org.rei.context.ContextPackage;
import org.rei.context.Crowd;
import org.rei.context.DynamicObject;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Human;
import org.rei.context.PhysicalObject;
import org.rei.context.Robot;
import org.rei.context.SimulationObject;
import org.rei.context.StaticObject;
import org.rei.context.Wall;

/**
 * Objects stand on floor centres, one per floor, and their catalogue types fit the role they play. A crowd's people
 * stand on its from floors, which no one else may start on.
 */
public class PlacementValidator extends ReiCheckBase {

	@Check
	public void checkTypeFitsRole(SimulationObject object) {
		ObjectType type = object.getType();
		if (type == null || type.eIsProxy()) {
			return; // untyped floors, walls and humans get the catalogue defaults; unknown names are linking errors
		}
		ObjectCategory expected = expectedCategory(object);
		boolean robotMismatch = object instanceof Robot && !(type instanceof RobotType);
		if (type.getCategory() != expected || robotMismatch) {
			error("Type " + type.getName() + " is a " + type.getCategory() + " type, but '" + object.getName()
					+ "' needs a " + expected + " type", object, ContextPackage.Literals.SIMULATION_OBJECT__TYPE,
					ReiIssueCodes.TYPE_CATEGORY);
		}
	}

	@Check
	public void checkOneObjectPerFloor(Environment environment) {
		Map<Floor, PhysicalObject> occupants = new HashMap<>();
		for (PhysicalObject object : environment.getOwnedObjects()) {
			occupy(occupants, object);
		}
		if (environment.getOwnedRobot() != null) {
			occupy(occupants, environment.getOwnedRobot());
		}
	}

	private void occupy(Map<Floor, PhysicalObject> occupants, PhysicalObject object) {
		if (object instanceof Crowd crowd) {
			occupy(occupants, crowd);
			return;
		}
		Floor floor = object.startFloor();
		if (floor == null || floor.eIsProxy()) {
			return;
		}
		PhysicalObject first = occupants.putIfAbsent(floor, object);
		if (first != null) {
			EReference feature = object instanceof Human human && human.getOwnedRoute() != null
					? ContextPackage.Literals.HUMAN__OWNED_ROUTE
					: object instanceof DynamicObject ? ContextPackage.Literals.DYNAMIC_OBJECT__OWNED_TRAJECTORY
					: ContextPackage.Literals.PHYSICAL_OBJECT__FLOOR;
			error("Floor " + floor.getName() + " is already taken by '" + first.getName()
					+ "': expected a free floor, one object per floor centre", object, feature,
					ReiIssueCodes.FLOOR_OCCUPIED);
		}
	}

	/** Each of the from floors, reported at the floor's name in the list; a floor named twice is taken once. */
	private void occupy(Map<Floor, PhysicalObject> occupants, Crowd crowd) {
		List<Floor> from = crowd.getFrom();
		for (int i = 0; i < from.size(); i++) {
			Floor floor = from.get(i);
			if (floor == null || floor.eIsProxy()) {
				continue;
			}
			PhysicalObject first = occupants.putIfAbsent(floor, crowd);
			if (first != null && first != crowd) {
				error("Floor " + floor.getName() + " is already taken by '" + first.getName() + "': expected a free "
						+ "floor, a crowd's people stand on its from floors alone", crowd,
						ContextPackage.Literals.CROWD__FROM, i, ReiIssueCodes.FLOOR_OCCUPIED);
			}
		}
	}

	private static ObjectCategory expectedCategory(SimulationObject object) {
		if (object instanceof Floor) {
			return ObjectCategory.FLOOR;
		}
		if (object instanceof Wall) {
			return ObjectCategory.WALL;
		}
		if (object instanceof Human || object instanceof Crowd) {
			return ObjectCategory.HUMAN;
		}
		if (object instanceof DynamicObject) {
			return ObjectCategory.DYNAMIC;
		}
		if (object instanceof Robot) {
			return ObjectCategory.ROBOT;
		}
		if (object instanceof StaticObject) {
			return ObjectCategory.STATIC;
		}
		throw new IllegalArgumentException("unexpected element " + object.eClass().getName());
	}
}
