/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.xtext.validation.Check;
import org.rei.context.ContextPackage;
import org.rei.context.Crowd;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.PhysicalObject;
import org.rei.context.StaticObject;
import org.rei.context.layout.FloorLayout;
import org.rei.context.people.PeoplePlacement;

/**
 * Crowds and groups (docs/language.md, "Crowds and groups"): as many people as the statement can have and as its
 * floors hold, a crowd's to floors free and reachable from its from floors, a rate and speeds people can keep. A
 * group's route is judged as every route ({@link RouteValidator}); a group's leader's start and a crowd's from floors
 * with every other start ({@link PlacementValidator#checkOneObjectPerFloor}); the names of their people with the
 * declared names ({@link NamingValidator#checkPeopleNames}).
 */
public class PeopleValidator extends ReiCheckBase {

	@Check
	public void checkCrowdSize(Crowd crowd) {
		if (crowd.getCount() < 1) {
			error("A crowd has 1 person or more: got " + crowd.getCount(), crowd, ContextPackage.Literals.CROWD__COUNT,
					ReiIssueCodes.TOO_FEW_PEOPLE);
		}
	}

	@Check
	public void checkGroupSize(Group group) {
		if (group.getCount() < 2) {
			error("A group has 2 people or more, its leader included: got " + group.getCount() + " (one person alone "
					+ "is a human with a route)", group, ContextPackage.Literals.GROUP__COUNT,
					ReiIssueCodes.TOO_FEW_PEOPLE);
		}
	}

	@Check
	public void checkRate(Crowd crowd) {
		if (crowd.isSetRate() && !(crowd.getRate() > 0)) {
			error("A crowd's rate is above 0 people a second: got " + RouteValidator.num(crowd.getRate()), crowd,
					ContextPackage.Literals.CROWD__RATE, ReiIssueCodes.NON_POSITIVE);
		}
	}

	@Check
	public void checkQueueEvery(Crowd crowd) {
		if (crowd.getQueue() != null && !(crowd.getQueueEvery() > 0)) {
			error("A queue lets one person pass every so many seconds, above 0: got "
					+ RouteValidator.num(crowd.getQueueEvery()), crowd, ContextPackage.Literals.CROWD__QUEUE_EVERY,
					ReiIssueCodes.NON_POSITIVE);
		}
	}

	/** As a route's ({@link RouteValidator#checkSpeed}). */
	@Check
	public void checkSpeed(Crowd crowd) {
		String problem = RouteValidator.speedProblem(crowd.getSpeed());
		if (problem != null) {
			error(problem, crowd, ContextPackage.Literals.CROWD__SPEED, ReiIssueCodes.OUT_OF_RANGE);
		}
	}

	/** As a route's ({@link RouteValidator#checkSpeedRange}). */
	@Check
	public void checkSpeedRange(Crowd crowd) {
		if (crowd.isSetSpeedTo()) {
			String problem = RouteValidator.rangeProblem(crowd.getSpeed(), crowd.getSpeedTo());
			if (problem != null) {
				error(problem, crowd, ContextPackage.Literals.CROWD__SPEED_TO, ReiIssueCodes.OUT_OF_RANGE);
			}
		}
	}

	@Check
	public void checkStart(Crowd crowd) {
		if (crowd.getStart() < 0) {
			error("A crowd sets off at 0s or later", crowd, ContextPackage.Literals.CROWD__START,
					ReiIssueCodes.NEGATIVE_TIME);
		}
	}

	/**
	 * The people walk to places on the to floors: no furniture there, and no one else's start (the robot's, a
	 * person's, another crowd's), as on the from floors. The crowd's own from floors may be among them.
	 */
	@Check
	public void checkToFloorsFree(Crowd crowd) {
		if (!(crowd.eContainer() instanceof Environment env)) {
			return;
		}
		Map<Floor, PhysicalObject> starts = PeoplePlacement.starts(env);
		List<Floor> to = crowd.getTo();
		for (int i = 0; i < to.size(); i++) {
			Floor floor = to.get(i);
			PhysicalObject there = floor == null || floor.eIsProxy() ? null : starts.get(floor);
			if (there != null && there != crowd) {
				error("Floor " + floor.getName() + " is already taken by '" + there.getName() + "': expected a free "
						+ "floor for the crowd's people to walk to", crowd, ContextPackage.Literals.CROWD__TO, i,
						ReiIssueCodes.FLOOR_OCCUPIED);
			}
		}
	}

	/**
	 * A crowd's people start in one part of the room and walk to floors of that part, as a goal is reachable from
	 * the robot's floor (MissionValidator): every floor through neighbouring floors from the first from floor.
	 */
	@Check
	public void checkFloorsConnected(Crowd crowd) {
		if (!(crowd.eContainer() instanceof Environment env) || crowd.getFrom().isEmpty()
				|| crowd.getFrom().get(0).eIsProxy()) {
			return;
		}
		Floor first = crowd.getFrom().get(0);
		Set<Floor> reachable = MissionValidator.reachableFrom(first, env);
		List<Floor> from = crowd.getFrom();
		for (int i = 1; i < from.size(); i++) {
			if (!from.get(i).eIsProxy() && !reachable.contains(from.get(i))) {
				error("Floor " + from.get(i).getName() + " cannot be reached from " + first.getName() + ", the first of "
						+ "the crowd's from floors, through neighbouring floors: a crowd starts in one part of the room",
						crowd, ContextPackage.Literals.CROWD__FROM, i, ReiIssueCodes.AREA_UNREACHABLE);
			}
		}
		List<Floor> to = crowd.getTo();
		for (int i = 0; i < to.size(); i++) {
			if (!to.get(i).eIsProxy() && !reachable.contains(to.get(i))) {
				error("Floor " + to.get(i).getName() + " cannot be reached from the crowd's from floors ("
						+ first.getName() + ") through neighbouring floors", crowd, ContextPackage.Literals.CROWD__TO,
						i, ReiIssueCodes.AREA_UNREACHABLE);
			}
		}
		Floor queue = crowd.getQueue();
		if (queue != null && !queue.eIsProxy() && !reachable.contains(queue)) {
			error("Floor " + queue.getName() + " cannot be reached from the crowd's from floors (" + first.getName()
					+ ") through neighbouring floors: the crowd queues on its way", crowd,
					ContextPackage.Literals.CROWD__QUEUE, ReiIssueCodes.AREA_UNREACHABLE);
		}
	}

	/**
	 * Each person of a queue stands on its floor's centre: no furniture on it, none reaching over it from another
	 * floor (the run would stop at its start, the queue's stop off the walkable area), as a route's stops
	 * ({@link RouteValidator#checkStopsNotUnderFurniture}).
	 */
	@Check
	public void checkQueueFree(Crowd crowd) {
		Floor queue = crowd.getQueue();
		if (queue == null || queue.eIsProxy() || !(crowd.eContainer() instanceof Environment env)) {
			return;
		}
		FloorLayout layout = roomLayout(env);
		if (layout.cellOf(queue).isEmpty()) {
			return;
		}
		double[] centre = layout.centreOf(queue);
		for (PhysicalObject object : env.getOwnedObjects()) {
			String problem = object instanceof StaticObject && object.getFloor() == queue
					? "A queue's floor " + queue.getName() + " is occupied by '" + object.getName()
							+ "': expected a free floor, where the first in line stands"
					: RouteValidator.covers(object, queue, centre, layout)
							? "A queue's floor " + queue.getName() + " lies under '" + object.getName() + "' (on "
									+ object.getFloor().getName() + "), which reaches over its centre: expected a "
									+ "floor a person can stand on"
							: null;
			if (problem != null) {
				error(problem, crowd, ContextPackage.Literals.CROWD__QUEUE, ReiIssueCodes.STOP_OCCUPIED);
				return;
			}
		}
	}

	/** Every person of the crowd has a place of its own on the from floors' lattice. */
	@Check
	public void checkFromFloorsHoldTheCrowd(Crowd crowd) {
		PeoplePlacement placement = placement(crowd, crowd.getFrom());
		if (placement == null || crowd.getCount() < 1) {
			return;
		}
		int holds = placement.from(crowd).size();
		if (holds < crowd.getCount()) {
			error("Crowd '" + crowd.getName() + "' of " + crowd.getCount() + ": its from floors hold at most "
					+ people(holds) + " of radius " + RouteValidator.num(placement.radius(crowd))
					+ " (name more floors, or fewer people)", crowd, ContextPackage.Literals.CROWD__COUNT,
					ReiIssueCodes.AREA_TOO_SMALL);
		}
	}

	/** The to floors hold one place at least (people share them when they hold fewer than the crowd has). */
	@Check
	public void checkToFloorsHoldSomeone(Crowd crowd) {
		PeoplePlacement placement = placement(crowd, crowd.getTo());
		if (placement != null && placement.to(crowd).isEmpty()) {
			error("Crowd '" + crowd.getName() + "': its to floors hold no person of radius "
					+ RouteValidator.num(placement.radius(crowd)) + " (name more floors, side by side)", crowd,
					ContextPackage.Literals.CROWD__TO, ReiIssueCodes.AREA_TOO_SMALL);
		}
	}

	/** The followers find places beside the leader: on its floor and the free floors next to it. */
	@Check
	public void checkGroupFits(Group group) {
		Floor leader = group.startFloor();
		PeoplePlacement placement = leader == null ? null : placement(group, List.of(leader));
		if (placement == null || group.getCount() < 2) {
			return;
		}
		int holds = 1 + placement.beside(group).size();
		if (holds < group.getCount()) {
			error("Group '" + group.getName() + "' of " + group.getCount() + ": " + leader.getName() + " and the free "
					+ "floors beside it hold at most " + people(holds) + " of radius "
					+ RouteValidator.num(placement.radius(group)) + " (start it where more floors are free, or with "
					+ "fewer people)", group, ContextPackage.Literals.GROUP__COUNT, ReiIssueCodes.AREA_TOO_SMALL);
		}
	}

	private static String people(int count) {
		return count == 1 ? "1 person" : count + " people";
	}

	/**
	 * The placement of the room of a crowd or group whose floors all have a place (else {@code null}: the names or
	 * the layout are reported elsewhere), computed once per validation of the room.
	 */
	private PeoplePlacement placement(PhysicalObject people, List<Floor> floors) {
		if (!(people.eContainer() instanceof Environment env) || floors.isEmpty()
				|| floors.stream().anyMatch(f -> f == null || f.eIsProxy())) {
			return null;
		}
		FloorLayout layout = roomLayout(env);
		PeoplePlacement placement = perRoom("people placement", env,
				() -> PeoplePlacement.of(env, layout, defaultHuman(env)));
		return floors.stream().anyMatch(f -> layout.cellOf(f).isEmpty()) ? null : placement;
	}
}
