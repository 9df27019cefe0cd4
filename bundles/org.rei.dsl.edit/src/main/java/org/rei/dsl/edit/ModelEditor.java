/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.ECollections;
import org.eclipse.emf.common.util.EList;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.rei.catalogue.ObjectType;
import org.rei.context.AsciiLayout;
import org.rei.context.Behaviour;
import org.rei.context.BuildingBlock;
import org.rei.context.ContextFactory;
import org.rei.context.ContextPackage;
import org.rei.context.ControlPoint;
import org.rei.context.Crowd;
import org.rei.context.Direction;
import org.rei.context.DynamicObject;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.GridLayout;
import org.rei.context.OccupancyLayout;
import org.rei.context.Human;
import org.rei.context.Mission;
import org.rei.context.NamedElement;
import org.rei.context.NavigationTask;
import org.rei.context.PhysicalObject;
import org.rei.context.Robot;
import org.rei.context.Route;
import org.rei.context.RouteStop;
import org.rei.context.SimulationObject;
import org.rei.context.StaticObject;
import org.rei.context.Task;
import org.rei.context.TestCase;
import org.rei.context.Trajectory;
import org.rei.context.Wall;
import org.rei.context.layout.FloorLayout;
import org.rei.dsl.edit.EditOperation.AddCrowd;
import org.rei.dsl.edit.EditOperation.AddDynamic;
import org.rei.dsl.edit.EditOperation.AddFloor;
import org.rei.dsl.edit.EditOperation.AddGoal;
import org.rei.dsl.edit.EditOperation.AddHuman;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.EditOperation.AddWall;
import org.rei.dsl.edit.EditOperation.DeleteObject;
import org.rei.dsl.edit.EditOperation.MoveGoal;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.RemoveFloor;
import org.rei.dsl.edit.EditOperation.RemoveGoal;
import org.rei.dsl.edit.EditOperation.RemoveWall;
import org.rei.dsl.edit.EditOperation.RotateObject;
import org.rei.dsl.edit.EditOperation.SetCrowd;
import org.rei.dsl.edit.EditOperation.SetRoute;
import org.rei.dsl.edit.EditOperation.SetTrajectory;
import org.rei.dsl.edit.EditOperation.Waypoint;

/**
 * Applies {@link EditOperation}s to the model, as the change serializer records them. Every name is looked up
 * before anything changes, so a refused operation alone leaves the model as it was; one refused later in a batch
 * leaves the earlier ones applied (the document then re-reads its text). New elements are built completely before
 * they join the model: the serializer writes them in one piece.
 */
final class ModelEditor {

	private static final Pattern NAME = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");
	private static final ContextFactory FACTORY = ContextFactory.eINSTANCE;

	private final TestCase testCase;
	private final Environment environment;
	private final IScopeProvider scopes;
	private final Set<String> reservedWords;
	private Map<String, BuildingBlock> blocks;
	/** The elements this batch added so far: a later operation of the batch must not change them (see below). */
	private final Set<EObject> created = new HashSet<>();

	/**
	 * An operation would change an element that an earlier operation of the same batch added. Xtext's partial
	 * serializer cannot place a change on an element the original text does not have and re-writes the whole room
	 * instead (statement order, blank lines and comments lost), so the document applies such a batch one operation
	 * after the other.
	 */
	static final class ChangesNewElementException extends RuntimeException {
		private static final long serialVersionUID = 1L;

		ChangesNewElementException(String name) {
			super("'" + name + "' was added by this batch and is changed again");
		}
	}

	/** @param reservedWords keywords that cannot be names (the grammar's, except those ValidID allows) */
	ModelEditor(TestCase testCase, IScopeProvider scopes, Set<String> reservedWords) {
		this.testCase = testCase;
		this.environment = testCase.getOwnedEnvironment();
		this.scopes = scopes;
		this.reservedWords = reservedWords;
		if (environment == null) {
			throw new EditRefusedException("Test case '" + testCase.getName() + "' has no room to edit");
		}
	}

	// (Java 17: no pattern matching in switch yet)
	void apply(EditOperation operation) {
		if (operation instanceof MoveObject move) {
			Floor floor = floor(move.floor());
			changing(placed(move.name(), "moved")).setFloor(floor);
		} else if (operation instanceof RotateObject rotate) {
			changing(placed(rotate.name(), "turned")).setYaw(rotate.yawDegrees());
		} else if (operation instanceof AddObject add) {
			addObject(add);
		} else if (operation instanceof AddHuman add) {
			addHuman(add);
		} else if (operation instanceof AddDynamic add) {
			addDynamic(add);
		} else if (operation instanceof DeleteObject delete) {
			deleteObject(delete);
		} else if (operation instanceof AddFloor add) {
			addFloor(add);
		} else if (operation instanceof RemoveFloor remove) {
			removeFloor(remove);
		} else if (operation instanceof AddWall add) {
			addWall(add);
		} else if (operation instanceof RemoveWall remove) {
			removeWall(remove);
		} else if (operation instanceof SetTrajectory set) {
			setTrajectory(set);
		} else if (operation instanceof SetRoute set) {
			setRoute(set);
		} else if (operation instanceof AddCrowd add) {
			addCrowd(add);
		} else if (operation instanceof SetCrowd set) {
			setCrowd(set);
		} else if (operation instanceof AddGoal add) {
			addGoal(add);
		} else if (operation instanceof RemoveGoal remove) {
			tasks("removed", remove.index(), false).remove(remove.index());
		} else if (operation instanceof MoveGoal move) {
			moveGoal(move);
		} else {
			throw new IllegalArgumentException("unknown operation " + operation);
		}
	}

	private void addObject(AddObject add) {
		checkNewName(add.name());
		ObjectType type = type(add.type());
		Floor floor = floor(add.floor());
		StaticObject object = FACTORY.createStaticObject();
		object.setName(add.name());
		object.setType(type);
		object.setFloor(floor);
		environment.getOwnedObjects().add(object);
		created.add(object);
	}

	/** Built whole, trajectory included, before it joins the room: the serializer writes it as one statement. */
	private void addHuman(AddHuman add) {
		checkNewName(add.name());
		ObjectType type = add.type() == null ? null : type(add.type());
		Human human = FACTORY.createHuman();
		human.setName(add.name());
		if (type != null) {
			human.setType(type);
		}
		human.setOwnedTrajectory(trajectory("human '" + add.name() + "'", add.points(), add.loop()));
		environment.getOwnedObjects().add(human);
		created.add(human);
	}

	/** As a human, with the type the grammar requires of a moving object. */
	private void addDynamic(AddDynamic add) {
		checkNewName(add.name());
		ObjectType type = type(add.type());
		DynamicObject mover = FACTORY.createDynamicObject();
		mover.setName(add.name());
		mover.setType(type);
		mover.setOwnedTrajectory(trajectory("moving object '" + add.name() + "'", add.points(), add.loop()));
		environment.getOwnedObjects().add(mover);
		created.add(mover);
	}

	/** A new trajectory through the waypoints; {@code loop} false is left unset (the grammar's default). */
	private Trajectory trajectory(String owner, List<Waypoint> waypoints, boolean loop) {
		requirePoints(owner, waypoints);
		Trajectory trajectory = FACTORY.createTrajectory();
		for (Waypoint waypoint : waypoints) {
			trajectory.getOwnedControlPoints().add(controlPoint(floor(waypoint.floor()), waypoint.seconds()));
		}
		if (loop) {
			trajectory.setLoop(true);
		}
		return trajectory;
	}

	private static void requirePoints(String owner, List<Waypoint> waypoints) {
		if (waypoints.isEmpty()) {
			throw new EditRefusedException("A trajectory is written with one control point at least (and needs two "
					+ "to move): " + owner + " would have none");
		}
	}

	private static ControlPoint controlPoint(Floor floor, double seconds) {
		ControlPoint point = FACTORY.createControlPoint();
		point.setFloor(floor);
		point.setTime(seconds);
		return point;
	}

	private void deleteObject(DeleteObject delete) {
		PhysicalObject object = object(delete.name());
		if (object instanceof Robot) {
			throw new EditRefusedException("'" + delete.name() + "' is the robot and a room has exactly one: move it "
					+ "instead of deleting it");
		}
		EcoreUtil.remove(object);
	}

	private void addFloor(AddFloor add) {
		explicitGraph("add floor " + add.name());
		checkNewName(add.name());
		Floor floor = FACTORY.createFloor();
		floor.setName(add.name());
		for (Map.Entry<Direction, String> side : add.neighbours().entrySet()) {
			floor.eSet(FloorLayout.feature(side.getKey()), block(side.getValue()));
		}
		// after the last floor, so that floors stay together in the text
		List<BuildingBlock> owned = environment.getOwnedBlocks();
		int index = 0;
		for (int i = 0; i < owned.size(); i++) {
			if (owned.get(i) instanceof Floor) {
				index = i + 1;
			}
		}
		owned.add(index, floor);
		blocks().put(floor.getName(), floor);
		created.add(floor);
	}

	private void removeFloor(RemoveFloor remove) {
		explicitGraph("remove floor " + remove.name());
		Floor floor = floor(remove.name());
		List<String> users = usersOf(floor);
		if (!users.isEmpty()) {
			throw new EditRefusedException("Floor " + floor.getName() + " is still used by " + String.join(", ", users)
					+ ": move or remove " + (users.size() == 1 ? "it" : "them") + " first");
		}
		unlink(floor);
		EcoreUtil.remove(floor);
		blocks().remove(floor.getName());
	}

	private void addWall(AddWall add) {
		explicitGraph("add wall " + add.name());
		checkNewName(add.name());
		Floor floor = floor(add.floor());
		BuildingBlock taken = FloorLayout.compute(environment).neighbour(floor, add.side());
		if (taken != null) {
			throw new EditRefusedException("The " + side(add.side()) + " of floor " + floor.getName() + " is "
					+ taken.getName() + " already: remove it first");
		}
		changing(floor);
		Wall wall = FACTORY.createWall();
		wall.setName(add.name());
		environment.getOwnedBlocks().add(wall);
		floor.eSet(FloorLayout.feature(add.side()), wall);
		blocks().put(wall.getName(), wall);
		created.add(wall);
	}

	private void removeWall(RemoveWall remove) {
		explicitGraph("remove wall " + remove.name());
		if (!(block(remove.name()) instanceof Wall wall)) {
			throw new EditRefusedException("'" + remove.name() + "' is a floor, not a wall");
		}
		unlink(wall);
		EcoreUtil.remove(wall);
		blocks().remove(wall.getName());
	}

	/** Changes the control points in place, so that a changed time or floor alone replaces just that token. */
	private void setTrajectory(SetTrajectory set) {
		PhysicalObject object = object(set.name());
		if (object instanceof Human person && person.getOwnedRoute() != null) {
			throw new EditRefusedException("'" + set.name() + "' walks a route, not a trajectory: change its route "
					+ "in the text");
		}
		if (!(object instanceof DynamicObject mover)) {
			throw new EditRefusedException("'" + set.name() + "' stands on a floor and has no trajectory: move it "
					+ "instead");
		}
		requirePoints("'" + set.name() + "'", set.points());
		changing(mover);
		List<Floor> floors = set.points().stream().map(p -> floor(p.floor())).toList();
		Trajectory trajectory = mover.getOwnedTrajectory();
		List<ControlPoint> points = trajectory.getOwnedControlPoints();
		for (int i = 0; i < set.points().size(); i++) {
			Waypoint wanted = set.points().get(i);
			if (i < points.size()) {
				ControlPoint point = points.get(i);
				if (point.getFloor() != floors.get(i)) {
					point.setFloor(floors.get(i));
				}
				if (point.getTime() != wanted.seconds()) {
					point.setTime(wanted.seconds());
				}
			} else {
				points.add(controlPoint(floors.get(i), wanted.seconds()));
			}
		}
		while (points.size() > set.points().size()) {
			points.remove(points.size() - 1);
		}
		if (trajectory.isLoop() != set.loop()) {
			trajectory.setLoop(set.loop());
		}
	}

	/**
	 * Changes the route in place, as a trajectory is changed: a changed floor, wait, speed, start, loop or behaviour
	 * alone replaces just its part of the line. A value equal to the grammar's default (speed 1.2, start 0, once,
	 * avoids) may then be left unwritten, as the text may leave it.
	 */
	private void setRoute(SetRoute set) {
		PhysicalObject object = object(set.name());
		if (!(object instanceof Human person) || person.getOwnedRoute() == null) {
			throw new EditRefusedException("'" + set.name() + "' " + (object instanceof DynamicObject
					? "follows a trajectory, not a route: change its trajectory instead"
					: "stands on a floor and has no route: move it instead"));
		}
		if (set.stops().isEmpty()) {
			throw new EditRefusedException("A route is written with one stop at least: '" + set.name()
					+ "' would have none");
		}
		// as the diagram and the text write it: the enum's name in lower case
		Behaviour behaviour = Behaviour.VALUES.stream()
				.filter(b -> b.getName().toLowerCase(Locale.ROOT).equals(set.behaviour())).findFirst().orElse(null);
		if (behaviour == null) {
			throw new EditRefusedException("'" + set.behaviour() + "' is not a behaviour: expected avoids, ignores, "
					+ "curious, scared or blocks");
		}
		List<Floor> floors = set.stops().stream().map(s -> floor(s.floor())).toList();
		changing(person);
		Route route = person.getOwnedRoute();
		List<RouteStop> stops = route.getOwnedStops();
		for (int i = 0; i < floors.size(); i++) {
			double wait = set.stops().get(i).waitSeconds();
			if (i < stops.size()) {
				RouteStop stop = stops.get(i);
				if (stop.getFloor() != floors.get(i)) {
					stop.setFloor(floors.get(i));
				}
				if (stop.getWait() != wait) {
					stop.setWait(wait);
				}
			} else {
				RouteStop stop = FACTORY.createRouteStop();
				stop.setFloor(floors.get(i));
				if (wait != 0) {
					stop.setWait(wait);
				}
				stops.add(stop);
			}
		}
		while (stops.size() > floors.size()) {
			stops.remove(stops.size() - 1);
		}
		if (route.getSpeed() != set.speed()) {
			route.setSpeed(set.speed());
			if (route.isSetSpeedTo()) {
				route.unsetSpeedTo(); // a range's (speed 1.0 to 1.4) person now walks at the one speed given
			}
		}
		if (route.getStart() != set.start()) {
			route.setStart(set.start());
		}
		if (route.isLoop() != set.loop()) {
			route.setLoop(set.loop());
		}
		if (route.getBehaviour() != behaviour) {
			route.setBehaviour(behaviour);
		}
	}

	/** Built whole, areas included, before it joins the room: the serializer writes it as one statement. */
	private void addCrowd(AddCrowd add) {
		checkNewName(add.name());
		String owner = "crowd '" + add.name() + "'";
		ObjectType type = add.type() == null ? null : type(add.type());
		List<Floor> from = area(owner, "from", add.from());
		List<Floor> to = area(owner, "to", add.to());
		checkCrowdNumbers(owner, add.count(), add.rate());
		Crowd crowd = FACTORY.createCrowd();
		crowd.setName(add.name());
		if (type != null) {
			crowd.setType(type);
		}
		crowd.setCount(add.count());
		crowd.getFrom().addAll(from);
		crowd.getTo().addAll(to);
		if (add.rate() != null) {
			crowd.setRate(add.rate());
		}
		environment.getOwnedObjects().add(crowd);
		created.add(crowd);
	}

	/**
	 * Changes a crowd in place, as a route is changed: a changed floor of an area, count or rate replaces just its
	 * token; an area's floors past the new ones go, new ones are appended.
	 */
	private void setCrowd(SetCrowd set) {
		PhysicalObject object = object(set.name());
		if (!(object instanceof Crowd crowd)) {
			throw new EditRefusedException("'" + set.name() + "' is not a crowd: only a crowd has from and to areas");
		}
		String owner = "crowd '" + set.name() + "'";
		List<Floor> from = area(owner, "from", set.from());
		List<Floor> to = area(owner, "to", set.to());
		checkCrowdNumbers(owner, set.count(), set.rate());
		changing(crowd);
		if (crowd.getCount() != set.count()) {
			crowd.setCount(set.count());
		}
		// the fewest moves, adds and removes (a floor may change places within an area: the list is unique)
		ECollections.setEList(crowd.getFrom(), from);
		ECollections.setEList(crowd.getTo(), to);
		if (set.rate() == null) {
			if (crowd.isSetRate()) {
				crowd.unsetRate();
			}
		} else if (!crowd.isSetRate() || crowd.getRate() != set.rate()) {
			crowd.setRate(set.rate());
		}
	}

	/** The floors of a crowd's area, each looked up with its place in the area in a refusal's message. */
	private List<Floor> area(String owner, String which, List<String> names) {
		if (names.isEmpty()) {
			throw new EditRefusedException("A crowd's " + which + " area is written with one floor at least: " + owner
					+ " would have none");
		}
		List<Floor> floors = new ArrayList<>();
		Set<String> seen = new HashSet<>();
		for (int i = 0; i < names.size(); i++) {
			String name = names.get(i);
			try {
				floors.add(floor(name));
			} catch (EditRefusedException e) {
				throw new EditRefusedException(owner + ", " + which + "[" + i + "]: " + e.getMessage());
			}
			if (!seen.add(name)) {
				throw new EditRefusedException(owner + ", " + which + "[" + i + "]: floor " + name + " is in the "
						+ which + " area twice");
			}
		}
		return floors;
	}

	private static void checkCrowdNumbers(String owner, int count, Double rate) {
		if (count < 1) {
			throw new EditRefusedException("A crowd has 1 person at least: " + owner + " would have " + count);
		}
		if (rate != null && !(rate > 0)) {
			throw new EditRefusedException("A crowd's rate is people a second, above 0: " + owner + " would have "
					+ rate + " (leave it out for all to set off at once)");
		}
	}

	private void addGoal(AddGoal add) {
		List<Task> tasks = tasks("added", add.index(), true);
		NavigationTask goal = FACTORY.createNavigationTask();
		goal.setGoal(floor(add.floor()));
		if (add.timeoutSeconds() != null) {
			goal.setTimeout(add.timeoutSeconds());
		}
		tasks.add(add.index(), goal);
		created.add(goal);
	}

	private void moveGoal(MoveGoal move) {
		EList<Task> tasks = tasks("moved", move.from(), false);
		if (move.to() < 0 || move.to() >= tasks.size()) {
			throw new EditRefusedException("Goal " + move.from() + " cannot move to " + move.to() + ": the mission has "
					+ tasks.size() + " goals (counted from 0)");
		}
		tasks.move(move.to(), move.from());
	}

	private EList<Task> tasks(String what, int index, boolean insert) {
		Mission mission = testCase.getOwnedMission();
		if (mission == null) {
			throw new EditRefusedException("Test case '" + testCase.getName() + "' has no mission whose goals could be "
					+ what + ": write 'mission NAME { goto FLOOR goto FLOOR }' first");
		}
		EList<Task> tasks = mission.getOwnedTasks();
		int last = insert ? tasks.size() : tasks.size() - 1;
		if (index < 0 || index > last) {
			throw new EditRefusedException("No goal " + index + " to be " + what + ": the mission has " + tasks.size()
					+ " goals (counted from 0)");
		}
		return tasks;
	}

	/** Furniture and the robot: what stands on a floor. */
	private PhysicalObject placed(String name, String what) {
		PhysicalObject object = object(name);
		if (object instanceof Human person && person.getOwnedRoute() != null) {
			throw new EditRefusedException("'" + name + "' walks a route and cannot be " + what + " as a whole: "
					+ "change its route in the text instead");
		}
		if (object instanceof DynamicObject) {
			throw new EditRefusedException("'" + name + "' follows a trajectory and cannot be " + what
					+ " as a whole: change its trajectory instead");
		}
		return object;
	}

	private PhysicalObject object(String name) {
		Robot robot = environment.getOwnedRobot();
		if (robot != null && name.equals(robot.getName())) {
			return robot;
		}
		for (PhysicalObject object : environment.getOwnedObjects()) {
			if (name.equals(object.getName())) {
				return object;
			}
		}
		throw new EditRefusedException("Room '" + environment.getName() + "' has no object, human or robot named '"
				+ name + "'");
	}

	private Floor floor(String name) {
		if (block(name) instanceof Floor floor) {
			return floor;
		}
		throw new EditRefusedException("'" + name + "' is a wall, not a floor");
	}

	private BuildingBlock block(String name) {
		BuildingBlock block = name == null ? null : blocks().get(name);
		if (block == null) {
			throw new EditRefusedException("Room '" + environment.getName() + "' has no floor or wall named '" + name
					+ "'");
		}
		return block;
	}

	/** By name, built once per batch: a room may have ten thousand floors. */
	private Map<String, BuildingBlock> blocks() {
		if (blocks == null) {
			blocks = new HashMap<>();
			for (BuildingBlock block : environment.getOwnedBlocks()) {
				blocks.putIfAbsent(block.getName(), block);
			}
		}
		return blocks;
	}

	/** A type of the catalogues in scope, found as the text's own references are. */
	private ObjectType type(String name) {
		IEObjectDescription description = name == null ? null
				: scopes.getScope(environment, ContextPackage.Literals.SIMULATION_OBJECT__TYPE)
						.getSingleElement(QualifiedName.create(name));
		if (description == null) {
			throw new EditRefusedException("No type '" + name + "' in the default catalogue or the imported ones");
		}
		EObject type = EcoreUtil.resolve(description.getEObjectOrProxy(), environment);
		if (!(type instanceof ObjectType objectType) || type.eIsProxy()) {
			throw new EditRefusedException("Type '" + name + "' cannot be loaded");
		}
		return objectType;
	}

	private void checkNewName(String name) {
		if (name == null || !NAME.matcher(name).matches() || reservedWords.contains(name)) {
			throw new EditRefusedException("'" + name + "' is not a name: expected letters, digits and '_', not "
					+ "starting with a digit, and not a keyword");
		}
		boolean taken = blocks().containsKey(name) || environment.getOwnedObjects().stream()
				.anyMatch(o -> name.equals(o.getName()))
				|| environment.getOwnedRobot() != null && name.equals(environment.getOwnedRobot().getName());
		if (taken) {
			throw new EditRefusedException("The name '" + name + "' is taken: names are unique in a test case");
		}
	}

	private void explicitGraph(String what) {
		if (environment.getOwnedLayout() instanceof GridLayout grid) {
			throw new EditRefusedException("Cannot " + what + ": room '" + environment.getName() + "' derives its "
					+ "floors and walls from its size " + grid.getColumns() + " x " + grid.getRows() + "; change the "
					+ "size, or write the room as a floor graph (floor A right B ...)");
		}
		if (environment.getOwnedLayout() instanceof OccupancyLayout occupancy) {
			throw new EditRefusedException("Cannot " + what + ": room '" + environment.getName() + "' derives its "
					+ "floors from the occupancy map " + occupancy.getMap() + "; change the map or the floor size");
		}
		if (environment.getOwnedLayout() instanceof AsciiLayout) {
			throw new EditRefusedException("Cannot " + what + ": room '" + environment.getName() + "' derives its "
					+ "floors and walls from its map; change the map, or write the room as a floor graph "
					+ "(floor A right B ...)");
		}
	}

	/** What refers to a floor other than its neighbours: objects on it, control points, route stops, goals. */
	private List<String> usersOf(Floor floor) {
		List<String> users = new ArrayList<>();
		for (EObject element : (Iterable<EObject>) () -> EcoreUtil.getAllContents(testCase, false)) {
			if (element instanceof PhysicalObject object && object.getFloor() == floor) {
				users.add(describe(object));
			} else if (element instanceof ControlPoint point && point.getFloor() == floor) {
				users.add("the trajectory of '" + ((NamedElement) point.eContainer().eContainer()).getName() + "'");
			} else if (element instanceof RouteStop stop && stop.getFloor() == floor) {
				users.add("the route of '" + ((NamedElement) stop.eContainer().eContainer()).getName() + "'");
			} else if (element instanceof NavigationTask task && task.getGoal() == floor) {
				users.add("goal " + ((Mission) task.eContainer()).getOwnedTasks().indexOf(task));
			}
		}
		return users.stream().distinct().collect(Collectors.toList());
	}

	/** Clears every neighbour reference to the block. */
	private void unlink(BuildingBlock block) {
		List<Runnable> unsets = new ArrayList<>();
		for (BuildingBlock other : environment.getOwnedBlocks()) {
			if (other instanceof Floor floor) {
				for (Direction side : Direction.VALUES) {
					EReference feature = FloorLayout.feature(side);
					if (floor.eGet(feature) == block) {
						changing(floor);
						unsets.add(() -> floor.eUnset(feature));
					}
				}
			}
		}
		unsets.forEach(Runnable::run);
	}

	/** The element, which this operation changes: refused for this batch when the batch added it. */
	private <T extends EObject> T changing(T element) {
		if (created.contains(element)) {
			throw new ChangesNewElementException(((NamedElement) element).getName());
		}
		return element;
	}

	private static String describe(SimulationObject object) {
		return (object instanceof Robot ? "the robot '" : "'") + object.getName() + "'";
	}

	private static String side(Direction side) {
		return side.getLiteral().toLowerCase() + " side";
	}
}
