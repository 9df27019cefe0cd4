/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.xtext.validation.Check;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.Shape;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Human;
import org.rei.context.PhysicalObject;
import org.rei.context.Route;
import org.rei.context.RouteStop;
import org.rei.context.StaticObject;
import org.rei.context.layout.FloorLayout;

/**
 * Routes of people who see the robot: a walking speed a person can walk, no time before the run, stops a person
 * can stand on and walk between. Where the person stands at the start (the first stop) is judged with every other
 * object's start by {@link PlacementValidator#checkOneObjectPerFloor}.
 */
public class RouteValidator extends ReiCheckBase {

	/** The fastest a route may ask for, in m/s: a run, beyond any walk the pedestrian model is made for. */
	static final double MAX_SPEED = 3.0;

	@Check
	public void checkSpeed(Route route) {
		String problem = speedProblem(route.getSpeed());
		if (problem != null) {
			error(problem, route, ContextPackage.Literals.ROUTE__SPEED, ReiIssueCodes.OUT_OF_RANGE);
		}
	}

	/** {@code speed 1.0 to 1.4}: a range from the slowest to the fastest, no faster than a single speed may be. */
	@Check
	public void checkSpeedRange(Route route) {
		if (route.isSetSpeedTo()) {
			String problem = rangeProblem(route.getSpeed(), route.getSpeedTo());
			if (problem != null) {
				error(problem, route, ContextPackage.Literals.ROUTE__SPEED_TO, ReiIssueCodes.OUT_OF_RANGE);
			}
		}
	}

	/** What is wrong with a walking speed, {@code null} when nothing is. */
	static String speedProblem(double speed) {
		return speed > 0 && speed <= MAX_SPEED ? null
				: "A walking speed is above 0 and at most " + num(MAX_SPEED) + " m/s (people walk at about 1.2-1.4): "
						+ "got " + num(speed);
	}

	/** What is wrong with the fastest speed of a range, {@code null} when nothing is. */
	static String rangeProblem(double speed, double speedTo) {
		return speedTo >= speed && speedTo <= MAX_SPEED ? null
				: "The fastest walking speed of a range is at least its slowest (" + num(speed) + ") and at most "
						+ num(MAX_SPEED) + " m/s: got " + num(speedTo);
	}

	@Check
	public void checkStart(Route route) {
		if (route.getStart() < 0) {
			error("A person sets off at 0s or later", route, ContextPackage.Literals.ROUTE__START,
					ReiIssueCodes.NEGATIVE_TIME);
		}
	}

	@Check
	public void checkWait(RouteStop stop) {
		if (stop.getWait() < 0) {
			error("A wait is 0s or longer", stop, ContextPackage.Literals.ROUTE_STOP__WAIT,
					ReiIssueCodes.NEGATIVE_TIME);
		}
	}

	/**
	 * No stop on furniture, as no goal is (MissionValidator): a person cannot stand at a table's centre. The first
	 * stop is the person's start, which the one-object-per-floor rule judges against furniture, the robot and the
	 * other starts.
	 */
	@Check
	public void checkStopsFree(Human human) {
		Route route = human.getOwnedRoute();
		if (route == null || route.getOwnedStops().size() < 2 || !(human.eContainer() instanceof Environment env)) {
			return;
		}
		Map<Floor, PhysicalObject> furniture = new HashMap<>();
		for (PhysicalObject object : env.getOwnedObjects()) {
			if (object instanceof StaticObject && object.getFloor() != null) {
				furniture.putIfAbsent(object.getFloor(), object);
			}
		}
		List<RouteStop> stops = route.getOwnedStops();
		for (RouteStop stop : stops.subList(1, stops.size())) {
			Floor floor = stop.getFloor();
			if (floor != null && !floor.eIsProxy() && furniture.containsKey(floor)) {
				error("Stop " + floor.getName() + " is occupied by '" + furniture.get(floor).getName()
						+ "': expected a free floor", stop, ContextPackage.Literals.ROUTE_STOP__FLOOR,
						ReiIssueCodes.STOP_OCCUPIED);
			}
		}
	}

	/**
	 * No stop under furniture that stands on another floor and reaches over this floor's centre (a banquet table 2.6
	 * m long over the next floors): the person's place is the floor's centre, off the walkable area the simulation's
	 * people have, and the run would stop at its start with "ann stands at (3.50, 2.50), outside the walkable area".
	 * The footprints are those the crowds' places keep clear of (PeoplePlacement): rectangles turned by their yaw,
	 * discs; furniture on a polygon is left to the run, whose open corner a person may stand in.
	 */
	@Check
	public void checkStopsNotUnderFurniture(Human human) {
		Route route = human.getOwnedRoute();
		if (route == null || !(human.eContainer() instanceof Environment env)) {
			return;
		}
		FloorLayout layout = roomLayout(env);
		for (RouteStop stop : route.getOwnedStops()) {
			Floor floor = stop.getFloor();
			if (floor == null || floor.eIsProxy() || layout.cellOf(floor).isEmpty()) {
				continue;
			}
			double[] centre = layout.centreOf(floor);
			for (PhysicalObject object : env.getOwnedObjects()) {
				if (covers(object, floor, centre, layout)) {
					error("Stop " + floor.getName() + " lies under '" + object.getName() + "' (on "
							+ object.getFloor().getName() + "), which reaches over its centre: expected a floor a "
							+ "person can stand on", stop, ContextPackage.Literals.ROUTE_STOP__FLOOR,
							ReiIssueCodes.STOP_OCCUPIED);
					break;
				}
			}
		}
	}

	/**
	 * People who see the robot stand apart where they start: the pedestrian model refuses two bodies that touch
	 * ("too close to agent"), which on floors smaller than two bodies (0.5 m for the default Human) two people on
	 * neighbouring floors do. Each stands on its first stop's centre; its radius is its type's, as the simulation
	 * gives it (a cylinder's, a box's circumradius).
	 */
	@Check
	public void checkStartsApart(Environment env) {
		List<Human> people = new java.util.ArrayList<>();
		for (PhysicalObject object : env.getOwnedObjects()) {
			if (object instanceof Human human && human.getOwnedRoute() != null
					&& !human.getOwnedRoute().getOwnedStops().isEmpty()) {
				Floor floor = human.getOwnedRoute().getOwnedStops().get(0).getFloor();
				if (floor != null && !floor.eIsProxy()) {
					people.add(human);
				}
			}
		}
		if (people.size() < 2) {
			return;
		}
		FloorLayout layout = roomLayout(env);
		for (int j = 1; j < people.size(); j++) {
			Human later = people.get(j);
			Floor floor = later.getOwnedRoute().getOwnedStops().get(0).getFloor();
			if (layout.cellOf(floor).isEmpty()) {
				continue;
			}
			double[] at = layout.centreOf(floor);
			for (int i = 0; i < j; i++) {
				Human earlier = people.get(i);
				Floor other = earlier.getOwnedRoute().getOwnedStops().get(0).getFloor();
				if (other == floor || layout.cellOf(other).isEmpty()) {
					continue; // one floor for two: the one-object-per-floor rule says so
				}
				double[] there = layout.centreOf(other);
				double apart = Math.hypot(at[0] - there[0], at[1] - there[1]);
				double need = radius(earlier) + radius(later);
				if (apart <= need + 1e-9) {
					error("'" + later.getName() + "' starts " + num(Math.round(apart * 1000) / 1000.0) + " m from '"
							+ earlier.getName() + "' (on " + other.getName() + ", centre to centre): their bodies "
							+ "touch, people need more than " + num(Math.round(need * 1000) / 1000.0)
							+ " m between them to stand", later.getOwnedRoute().getOwnedStops().get(0),
							ContextPackage.Literals.ROUTE_STOP__FLOOR, ReiIssueCodes.FLOOR_OCCUPIED);
					break;
				}
			}
		}
	}

	/** A person's radius in the pedestrian model: its type's (the default Human's when it names none). */
	private static double radius(Human human) {
		ObjectType type = human.getType();
		if (type == null || type.eIsProxy()) {
			type = defaultHuman(human);
		}
		if (type == null || type.eIsProxy()) {
			return 0.25;
		}
		return type.getShape() == Shape.CYLINDER ? type.getSizeX() / 2
				: Math.hypot(type.getSizeX(), type.getSizeY()) / 2;
	}

	/** Whether furniture on another floor than {@code floor} covers the point {@code p}. */
	static boolean covers(PhysicalObject object, Floor floor, double[] p, FloorLayout layout) {
		if (!(object instanceof StaticObject) || object.getFloor() == null || object.getFloor() == floor
				|| object.getType() == null || object.getType().eIsProxy() || !object.getType().getVertices().isEmpty()
				|| layout.cellOf(object.getFloor()).isEmpty()) {
			return false;
		}
		ObjectType type = object.getType();
		double[] at = layout.centreOf(object.getFloor());
		double dx = p[0] - at[0];
		double dy = p[1] - at[1];
		if (type.getShape() == Shape.CYLINDER) {
			return Math.hypot(dx, dy) < type.getSizeX() / 2;
		}
		double yaw = Math.toRadians(object.getYaw());
		double u = Math.cos(yaw) * dx + Math.sin(yaw) * dy;
		double v = -Math.sin(yaw) * dx + Math.cos(yaw) * dy;
		return Math.abs(u) < type.getSizeX() / 2 && Math.abs(v) < type.getSizeY() / 2;
	}

	/**
	 * Each stop can be reached from the one before through neighbouring floors, as a goal from the robot's floor
	 * (MissionValidator): the pedestrian model finds the way in between, but there must be one. One search per
	 * connected part of the room the route enters, not one per stop.
	 */
	@Check
	public void checkStopsConnected(Human human) {
		Route route = human.getOwnedRoute();
		if (route == null || !(human.eContainer() instanceof Environment env)) {
			return;
		}
		Floor previous = null;
		Set<Floor> reachable = null;
		for (RouteStop stop : route.getOwnedStops()) {
			Floor floor = stop.getFloor();
			if (floor == null || floor.eIsProxy()) {
				continue;
			}
			if (reachable != null && !reachable.contains(floor)) {
				error("Stop " + floor.getName() + " cannot be reached from the stop before it, " + previous.getName()
						+ ", through neighbouring floors", stop, ContextPackage.Literals.ROUTE_STOP__FLOOR,
						ReiIssueCodes.STOP_UNREACHABLE);
				reachable = null;
			}
			if (reachable == null) {
				reachable = MissionValidator.reachableFrom(floor, env);
			}
			previous = floor;
		}
	}

	static String num(double v) {
		return v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v) : String.valueOf(v);
	}
}
