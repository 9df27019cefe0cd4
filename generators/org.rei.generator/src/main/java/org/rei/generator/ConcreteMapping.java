/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceImpl;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.Shape;
import org.rei.catalogue.util.Polygons;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.Behaviour;
import org.rei.context.BuildingBlock;
import org.rei.context.ControlPoint;
import org.rei.context.Crowd;
import org.rei.context.DynamicObject;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.Human;
import org.rei.context.Mission;
import org.rei.context.NavigationTask;
import org.rei.context.PhysicalObject;
import org.rei.context.Robot;
import org.rei.context.Route;
import org.rei.context.RouteStop;
import org.rei.context.StaticObject;
import org.rei.context.Task;
import org.rei.context.TestCase;
import org.rei.context.Wall;
import org.rei.context.layout.FloorLayout;
import org.rei.context.layout.WallPlacement;
import org.rei.context.people.PeoplePlacement;
import org.rei.context.people.WalkingSpeed;
import org.rei.mission.GeometricGoal;
import org.rei.mission.MissionDescription;
import org.rei.mission.MissionFactory;
import org.rei.mission.Pose2D;
import org.rei.runtime.ConcreteEnvironment;
import org.rei.runtime.ConcreteObject;
import org.rei.runtime.Pose;
import org.rei.runtime.RuntimeFactory;

/**
 * The model-to-model step: abstract test case + floor layout to the concrete environment (every body with its
 * pose and size) and the concrete mission (goals as world-frame poses), thesis 4.1.3 and 4.3.1. Crowds and groups
 * are expanded here into the people they are (NAME_1 to NAME_N, each a HUMAN body and a {@link Person}), placed by
 * the {@link PeoplePlacement} the validator counts with, so the simulation only ever sees single people.
 */
final class ConcreteMapping {

	/** Result of one mapping; the EGL templates read these. */
	record Result(ConcreteEnvironment environment, MissionDescription mission, List<ConcreteObject> bodies,
			List<ConcreteObject> floors, ConcreteObject robot, List<DynamicObject> animated, List<Person> people,
			Map<PhysicalObject, ConcreteObject> concrete, List<ObjectType> types) {
	}

	private final ObjectType floorType;
	private final ObjectType wallType;
	private final ObjectType humanType;
	private final ObjectType robotType;

	ConcreteMapping(Catalogue defaults) {
		this.floorType = require(defaults, "Floor");
		this.wallType = require(defaults, "Wall");
		this.humanType = require(defaults, "Human");
		this.robotType = require(defaults, "Waffle");
	}

	private static ObjectType require(Catalogue catalogue, String name) {
		return Catalogues.find(catalogue, name)
				.orElseThrow(() -> new IllegalStateException("default catalogue has no " + name + " type"));
	}

	/** The type used for walls without one; the layout must agree with the generator on wall thickness. */
	ObjectType defaultWallType() {
		return wallType;
	}

	Result map(TestCase testCase, FloorLayout layout, MapRoom mapRoom) throws GenerationException {
		Environment env = testCase.getOwnedEnvironment();
		double size = env.getFloorSize();
		ConcreteEnvironment world = RuntimeFactory.eINSTANCE.createConcreteEnvironment();
		world.setName(env.getName());
		world.setFloorSize(size);
		List<ConcreteObject> bodies = new ArrayList<>();
		List<ConcreteObject> floors = new ArrayList<>();
		List<DynamicObject> animated = new ArrayList<>();
		List<Person> people = new ArrayList<>();
		PeoplePlacement placement = null;
		Map<PhysicalObject, ConcreteObject> concrete = new HashMap<>();
		Map<String, ObjectType> types = new LinkedHashMap<>();

		for (BuildingBlock block : env.getOwnedBlocks()) {
			ConcreteObject body;
			if (block instanceof Floor floor) {
				ObjectType type = typeOf(floor.getType(), floorType, types);
				double[] centre = layout.centreOf(floor);
				// the floor's top surface is z = 0
				body = body(floor.getName(), type, ObjectCategory.FLOOR, size, size, type.getSizeZ(), centre[0],
						centre[1], -type.getSizeZ() / 2, 0, floor);
				floors.add(body);
			} else if (block instanceof Wall wall) {
				WallPlacement p = layout.placementOf(wall)
						.orElseThrow(() -> new GenerationException("wall " + wall.getName() + " has no place"));
				typeOf(p.type(), wallType, types);
				body = body(wall.getName(), p.type(), ObjectCategory.WALL, p.sizeX(), p.sizeY(), p.sizeZ(), p.x(),
						p.y(), p.z(), 0, p.floor());
			} else {
				continue;
			}
			bodies.add(body);
		}
		if (mapRoom != null) {
			bodies.addAll(mapWalls(mapRoom, types));
		}
		for (PhysicalObject object : env.getOwnedObjects()) {
			if (object instanceof Crowd || object instanceof Group) {
				if (placement == null) {
					placement = PeoplePlacement.of(env, layout, humanType);
				}
				if (object instanceof Crowd crowd) {
					crowd(crowd, layout, placement, types, bodies, people);
				} else {
					group((Group) object, layout, placement, types, bodies, people);
				}
				continue;
			}
			ConcreteObject body = physical(object, layout, types);
			bodies.add(body);
			concrete.put(object, body);
			if (object instanceof Human human && human.getOwnedRoute() != null) {
				// a person who sees the robot: a body like any human, moved by the pedestrian model, not on rails
				checkRoute(human, layout);
				people.add(person(human.getName(), human.getOwnedRoute(), human.getType(), null, layout));
			} else if (object instanceof DynamicObject dynamic) {
				checkTrajectory(dynamic, layout);
				animated.add(dynamic);
			}
		}
		world.getOwnedObjects().addAll(bodies);
		ConcreteObject robot = null;
		if (env.getOwnedRobot() != null) {
			robot = physical(env.getOwnedRobot(), layout, types);
			world.getOwnedObjects().add(robot); // last: it is no entry of objects[] but a body of the world
		}
		MissionDescription mission = mission(testCase, env, robot, layout);
		contain(world, "world.runtime");
		contain(mission, "mission.mission");
		return new Result(world, mission, bodies, floors, robot, animated, people, concrete,
				List.copyOf(types.values()));
	}

	/**
	 * The obstacle rectangles of an occupancy room as walls of the default Wall type's height and colour, posed at
	 * their centres (Python's {@code rei.maps.box_of}); they stand on no floor.
	 */
	private List<ConcreteObject> mapWalls(MapRoom room, Map<String, ObjectType> types) {
		List<org.rei.maps.CellRect> rects = room.walls();
		List<ConcreteObject> walls = new ArrayList<>(rects.size());
		if (!rects.isEmpty()) {
			typeOf(null, wallType, types);
		}
		double height = wallType.getSizeZ();
		for (org.rei.maps.CellRect rect : rects) {
			double[] box = room.map().boxOf(rect);
			walls.add(body(MapRoom.wallName(rect), wallType, ObjectCategory.WALL, box[2], box[3], height, box[0],
					box[1], height / 2, 0, null));
		}
		return walls;
	}

	/** InMemoryEmfModel needs a resource; nothing is ever saved. */
	private static void contain(org.eclipse.emf.ecore.EObject root, String name) {
		Resource resource = new ResourceImpl(URI.createURI("rei:/" + name));
		resource.getContents().add(root);
	}

	private ConcreteObject physical(PhysicalObject object, FloorLayout layout, Map<String, ObjectType> types)
			throws GenerationException {
		Floor floor = object.startFloor();
		if (floor == null || layout.cellOf(floor).isEmpty()) {
			throw new GenerationException(object.getName() + " does not stand on a floor of the room");
		}
		ObjectCategory category;
		ObjectType fallback;
		if (object instanceof Robot) {
			category = ObjectCategory.ROBOT;
			fallback = robotType;
		} else if (object instanceof Human) {
			category = ObjectCategory.HUMAN;
			fallback = humanType;
		} else if (object instanceof DynamicObject) {
			category = ObjectCategory.DYNAMIC;
			fallback = null;
		} else if (object instanceof StaticObject) {
			category = ObjectCategory.STATIC;
			fallback = null;
		} else {
			throw new GenerationException("unknown kind of object: " + object.eClass().getName());
		}
		if (object.getType() == null && fallback == null) {
			throw new GenerationException(object.getName() + " has no type");
		}
		ObjectType type = typeOf(object.getType(), fallback, types);
		double[] centre = layout.centreOf(floor);
		double sizeX = type.getSizeX();
		double sizeY = type.getShape() == Shape.CYLINDER ? sizeX : type.getSizeY();
		if (Polygons.isPolygon(type)) { // its bounding box, centred on the floor centre as a box is
			double[] b = Polygons.bounds(Polygons.points(type));
			sizeX = b[2] - b[0];
			sizeY = b[3] - b[1];
		}
		// bodies are posed at their centre, the robot at its base on the ground
		double z = category == ObjectCategory.ROBOT ? 0 : type.getSizeZ() / 2;
		return body(object.getName(), type, category, sizeX, sizeY, type.getSizeZ(), centre[0], centre[1], z,
				Math.toRadians(object.getYaw()), floor);
	}

	private static ObjectType typeOf(ObjectType declared, ObjectType fallback, Map<String, ObjectType> used) {
		ObjectType type = declared != null ? declared : fallback;
		used.putIfAbsent(type.getName(), type);
		return type;
	}

	private static ConcreteObject body(String name, ObjectType type, ObjectCategory category, double sizeX,
			double sizeY, double sizeZ, double x, double y, double z, double yaw, Floor standsOn) {
		ConcreteObject body = RuntimeFactory.eINSTANCE.createConcreteObject();
		body.setName(name);
		body.setType(type);
		body.setCategory(category);
		body.setSizeX(sizeX);
		body.setSizeY(sizeY);
		body.setSizeZ(sizeZ);
		Pose pose = RuntimeFactory.eINSTANCE.createPose();
		pose.setX(x);
		pose.setY(y);
		pose.setZ(z);
		pose.setYaw(yaw);
		body.setPose(pose);
		body.setStandsOn(standsOn);
		return body;
	}

	private static void checkTrajectory(DynamicObject object, FloorLayout layout) throws GenerationException {
		if (object.getOwnedTrajectory() == null) {
			return;
		}
		double previous = Double.NEGATIVE_INFINITY;
		for (ControlPoint point : object.getOwnedTrajectory().getOwnedControlPoints()) {
			if (point.getFloor() == null || layout.cellOf(point.getFloor()).isEmpty()) {
				throw new GenerationException("a control point of " + object.getName() + " is not on a floor of the room");
			}
			if (!(point.getTime() > previous)) {
				throw new GenerationException("control point times of " + object.getName() + " must strictly increase");
			}
			previous = point.getTime();
		}
	}

	/**
	 * A crowd's people: person i stands on the from floors' lattice point i - 1 and walks to the to floors' point
	 * (i - 1) mod their number, setting off (i - 1) / rate seconds after the crowd's start.
	 */
	private void crowd(Crowd crowd, FloorLayout layout, PeoplePlacement placement, Map<String, ObjectType> types,
			List<ConcreteObject> bodies, List<Person> people) throws GenerationException {
		onFloors(crowd.getFrom(), "a from floor of crowd " + crowd.getName(), layout);
		onFloors(crowd.getTo(), "a to floor of crowd " + crowd.getName(), layout);
		List<PeoplePlacement.Spot> from = placement.from(crowd);
		List<PeoplePlacement.Spot> to = placement.to(crowd);
		int count = crowd.getCount();
		if (count < 1 || from.size() < count || to.isEmpty()) {
			throw new GenerationException("crowd " + crowd.getName() + " of " + count + ": its from floors hold "
					+ from.size() + " and its to floors " + to.size() + " people of radius "
					+ Numbers.format(placement.radius(crowd)));
		}
		ObjectType type = typeOf(crowd.getType(), humanType, types);
		WalkingSpeed speed = WalkingSpeed.of(crowd);
		Person.Stop queue = null;
		if (crowd.getQueue() != null) {
			onFloors(List.of(crowd.getQueue()), "the queue floor of crowd " + crowd.getName(), layout);
			double[] centre = layout.centreOf(crowd.getQueue());
			queue = new Person.Stop(crowd.getQueue().getName(), centre[0], centre[1], 0, crowd.getQueueEvery());
		}
		for (int i = 1; i <= count; i++) {
			PeoplePlacement.Spot start = from.get(i - 1);
			PeoplePlacement.Spot target = to.get((i - 1) % to.size());
			String name = crowd.getName() + "_" + i;
			bodies.add(humanBody(name, type, start.x(), start.y(), start.floor()));
			double setsOff = crowd.getStart() + (crowd.isSetRate() ? (i - 1) / crowd.getRate() : 0);
			List<Person.Stop> route = queue == null ? List.of(stop(start), stop(target))
					: List.of(stop(start), queue, stop(target));
			people.add(new Person(name, behaviour(crowd.getBehaviour()), speed.speed(), speed.speedTo(), setsOff,
					crowd.isLoop(), null, route));
		}
	}

	/**
	 * A group's people: NAME_1, its leader, on the first stop's centre as a routed human; the others on the places
	 * beside it, nearest first; all with the group's route, speed, start, loop and behaviour.
	 */
	private void group(Group group, FloorLayout layout, PeoplePlacement placement, Map<String, ObjectType> types,
			List<ConcreteObject> bodies, List<Person> people) throws GenerationException {
		checkRoute(group, layout);
		Floor first = group.startFloor();
		if (first == null) {
			throw new GenerationException("group " + group.getName() + " has no route to stand on");
		}
		List<PeoplePlacement.Spot> beside = placement.beside(group);
		int count = group.getCount();
		if (count < 2 || beside.size() < count - 1) {
			throw new GenerationException("group " + group.getName() + " of " + count + ": " + first.getName()
					+ " and the free floors beside it hold " + (1 + beside.size()) + " people of radius "
					+ Numbers.format(placement.radius(group)));
		}
		ObjectType type = typeOf(group.getType(), humanType, types);
		double[] centre = layout.centreOf(first);
		for (int i = 1; i <= count; i++) {
			String name = group.getName() + "_" + i;
			if (i == 1) {
				bodies.add(humanBody(name, type, centre[0], centre[1], first));
			} else {
				PeoplePlacement.Spot spot = beside.get(i - 2);
				bodies.add(humanBody(name, type, spot.x(), spot.y(), spot.floor()));
			}
			people.add(person(name, group.getOwnedRoute(), group.getType(), group.getName(), layout));
		}
	}

	/** A person on a route of floor centres: a routed human, or one of a group. */
	private static Person person(String name, Route route, ObjectType type, String group, FloorLayout layout) {
		List<Person.Stop> stops = new ArrayList<>();
		for (RouteStop stop : route.getOwnedStops()) {
			double[] centre = layout.centreOf(stop.getFloor());
			stops.add(new Person.Stop(stop.getFloor().getName(), centre[0], centre[1], stop.getWait()));
		}
		WalkingSpeed speed = WalkingSpeed.of(route, type);
		return new Person(name, behaviour(route.getBehaviour()), speed.speed(), speed.speedTo(), route.getStart(),
				route.isLoop(), group, stops);
	}

	private static Person.Stop stop(PeoplePlacement.Spot spot) {
		return new Person.Stop(spot.floor().getName(), spot.x(), spot.y(), 0);
	}

	/** As animation.json names it: the grammar's word. */
	private static String behaviour(Behaviour behaviour) {
		return behaviour.getName().toLowerCase(Locale.ROOT);
	}

	/** A person's body, as {@link #physical} makes a human's, at a point of a floor instead of its centre. */
	private static ConcreteObject humanBody(String name, ObjectType type, double x, double y, Floor floor) {
		double sizeY = type.getShape() == Shape.CYLINDER ? type.getSizeX() : type.getSizeY();
		return body(name, type, ObjectCategory.HUMAN, type.getSizeX(), sizeY, type.getSizeZ(), x, y,
				type.getSizeZ() / 2, 0, floor);
	}

	private static void onFloors(List<Floor> floors, String what, FloorLayout layout) throws GenerationException {
		for (Floor floor : floors) {
			if (floor == null || layout.cellOf(floor).isEmpty()) {
				throw new GenerationException(what + " is not a floor of the room");
			}
		}
	}

	private static void checkRoute(Human human, FloorLayout layout) throws GenerationException {
		for (RouteStop stop : human.getOwnedRoute().getOwnedStops()) {
			if (stop.getFloor() == null || layout.cellOf(stop.getFloor()).isEmpty()) {
				throw new GenerationException("a stop of " + human.getName() + "'s route is not on a floor of the room");
			}
		}
	}

	private static MissionDescription mission(TestCase testCase, Environment env, ConcreteObject robot,
			FloorLayout layout) throws GenerationException {
		MissionDescription description = MissionFactory.eINSTANCE.createMissionDescription();
		description.setEnvironment(env.getName());
		if (robot != null) {
			description.setRobot(robot.getName());
			description.setStart(pose2D(robot.getPose().getX(), robot.getPose().getY(), robot.getPose().getYaw()));
		}
		Mission mission = testCase.getOwnedMission();
		if (mission == null) {
			return description;
		}
		description.setName(mission.getName());
		int index = 0;
		for (Task task : mission.getOwnedTasks()) {
			if (!(task instanceof NavigationTask navigation)) {
				throw new GenerationException("unsupported task: " + task.eClass().getName());
			}
			Floor floor = navigation.getGoal();
			if (floor == null || layout.cellOf(floor).isEmpty()) {
				throw new GenerationException("goal " + index + " of " + mission.getName() + " is not a floor of the room");
			}
			double[] centre = layout.centreOf(floor);
			GeometricGoal goal = MissionFactory.eINSTANCE.createGeometricGoal();
			goal.setIndex(index++);
			goal.setFloor(floor.getName());
			goal.setPose(pose2D(centre[0], centre[1], 0));
			goal.setTolerance(mission.getGoalTolerance());
			goal.setTimeout(navigation.isSetTimeout() ? navigation.getTimeout() : mission.getTaskTimeout());
			description.getOwnedGoals().add(goal);
		}
		return description;
	}

	private static Pose2D pose2D(double x, double y, double yaw) {
		Pose2D pose = MissionFactory.eINSTANCE.createPose2D();
		pose.setX(x);
		pose.setY(y);
		pose.setYaw(yaw);
		return pose;
	}
}
