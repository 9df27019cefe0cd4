/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.diagram;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.eclipse.emf.ecore.resource.ResourceSet;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.RobotType;
import org.rei.catalogue.util.Catalogues;
import org.rei.catalogue.util.Polygons;
import org.rei.catalogue.util.RobotDescriptions;
import org.rei.context.AsciiLayout;
import org.rei.context.BuildingBlock;
import org.rei.context.ControlPoint;
import org.rei.context.Crowd;
import org.rei.context.DynamicObject;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.GridLayout;
import org.rei.context.Group;
import org.rei.context.OccupancyLayout;
import org.rei.context.Human;
import org.rei.context.MonitorSpec;
import org.rei.context.NavigationTask;
import org.rei.context.PhysicalObject;
import org.rei.context.Robot;
import org.rei.context.Route;
import org.rei.context.RouteStop;
import org.rei.context.Task;
import org.rei.context.TestCase;
import org.rei.context.layout.Cell;
import org.rei.context.layout.FloorLayout;
import org.rei.context.layout.WallPlacement;
import org.rei.dsl.derived.DerivedMarker;
import org.rei.dsl.derived.RoomDesugaring;

/**
 * Builds a {@link Diagram} from a test case. Floor cells, centres and wall places come from {@link FloorLayout}, the
 * mapping the generators use, so the diagram shows the room the simulator will build.
 */
public final class DiagramBuilder {

	private DiagramBuilder() {
	}

	public static Diagram of(TestCase testCase) {
		Environment environment = testCase.getOwnedEnvironment();
		if (environment == null) {
			return new Diagram(testCase.getName(), null, List.of(), null, List.of(), mission(testCase, null),
					monitor(testCase.getOwnedMonitor()), List.of(), List.of());
		}
		FloorLayout layout = RoomDesugaring.layoutOf(environment); // a map room: in the map's frame
		Catalogue defaults = Catalogues.loadDefault(resourceSet(testCase));
		List<Diagram.Item> objects = new ArrayList<>();
		List<Diagram.Mover> movers = new ArrayList<>();
		List<Diagram.CrowdAreas> crowds = new ArrayList<>();
		List<Diagram.GroupRoute> groups = new ArrayList<>();
		for (PhysicalObject object : environment.getOwnedObjects()) {
			// as many people as the line says, placed by the generator: drawn as their areas or route, not as movers
			if (object instanceof Crowd crowd) {
				crowds.add(crowd(crowd, layout, defaults));
				continue;
			}
			if (object instanceof Group group) {
				groups.add(new Diagram.GroupRoute(group.getName(), group.getCount(),
						footprint(group.getType(), defaults, "Human"),
						group.getOwnedRoute() == null ? null : route(group.getOwnedRoute(), layout),
						group.getOwnedRoute() != null && group.getOwnedRoute().isLoop()));
				continue;
			}
			if (object instanceof DynamicObject mover) {
				movers.add(mover(mover, layout, defaults));
			} else {
				objects.add(item(object, "object", layout, defaults));
			}
		}
		Robot robot = environment.getOwnedRobot();
		return new Diagram(testCase.getName(), room(environment, layout, defaults), objects,
				robot == null ? null : item(robot, "robot", layout, defaults), movers, mission(testCase, layout),
				monitor(testCase.getOwnedMonitor()), crowds, groups);
	}

	private static Diagram.CrowdAreas crowd(Crowd crowd, FloorLayout layout, Catalogue defaults) {
		return new Diagram.CrowdAreas(crowd.getName(), crowd.getCount(), footprint(crowd.getType(), defaults, "Human"),
				area(crowd.getFrom(), layout), area(crowd.getTo(), layout), crowd.isSetRate() ? crowd.getRate() : null,
				crowd.getSpeed(), crowd.isLoop(), crowd.getBehaviour().getName().toLowerCase(Locale.ROOT));
	}

	private static List<Diagram.Area> area(List<Floor> floors, FloorLayout layout) {
		List<Diagram.Area> area = new ArrayList<>();
		for (Floor floor : floors) {
			double[] centre = centre(floor, layout);
			area.add(new Diagram.Area(name(floor), centre == null ? null : centre[0],
					centre == null ? null : centre[1]));
		}
		return area;
	}

	private static Diagram.Room room(Environment environment, FloorLayout layout, Catalogue defaults) {
		List<Diagram.FloorCell> floors = new ArrayList<>();
		for (BuildingBlock block : environment.getOwnedBlocks()) {
			if (block instanceof Floor floor) {
				Cell cell = layout.cellOf(floor).orElse(null);
				double[] centre = cell == null ? null : layout.centreOf(floor);
				floors.add(new Diagram.FloorCell(floor.getName(), typeName(floor.getType(), defaults, "Floor"),
						cell == null ? null : cell.x(), cell == null ? null : cell.y(),
						centre == null ? null : centre[0], centre == null ? null : centre[1],
						!DerivedMarker.isDerived(floor)));
			}
		}
		List<Diagram.WallSide> walls = new ArrayList<>();
		for (WallPlacement wall : layout.walls()) {
			walls.add(new Diagram.WallSide(wall.wall().getName(), wall.type().getName(), wall.floor().getName(),
					wall.side().getLiteral().toLowerCase(), wall.x(), wall.y(), wall.sizeX(), wall.sizeY(),
					!DerivedMarker.isDerived(wall.wall())));
		}
		String form = environment.getOwnedLayout() instanceof GridLayout ? "grid"
				: environment.getOwnedLayout() instanceof AsciiLayout ? "map"
				: environment.getOwnedLayout() instanceof OccupancyLayout ? "occupancy" : "graph";
		return new Diagram.Room(environment.getName(), form, environment.getFloorSize(), layout.columns(),
				layout.rows(), floors, walls, occupancyMap(environment));
	}

	/** The map of an occupancy room, {@code null} for another room or a map that cannot be read. */
	private static Diagram.OccupancyMap occupancyMap(Environment environment) {
		if (!(environment.getOwnedLayout() instanceof OccupancyLayout layout)) {
			return null;
		}
		try {
			org.rei.maps.OccupancyMap map = RoomDesugaring.mapOf(layout);
			return new Diagram.OccupancyMap(map.yaml().toAbsolutePath().toString(),
					map.image().toAbsolutePath().toString(), map.resolution(), map.originX(), map.originY(),
					map.width(), map.height(), layout.isUnknownFree());
		} catch (org.rei.maps.MapException e) {
			return null; // the validator reports it
		}
	}

	private static Diagram.Item item(PhysicalObject object, String kind, FloorLayout layout, Catalogue defaults) {
		Floor floor = object.getFloor();
		double[] centre = centre(floor, layout);
		return new Diagram.Item(object.getName(), kind, name(floor), object.getYaw(), centre == null ? null : centre[0],
				centre == null ? null : centre[1], footprint(object.getType(), defaults, null));
	}

	private static Diagram.Mover mover(DynamicObject mover, FloorLayout layout, Catalogue defaults) {
		List<Diagram.Waypoint> points = new ArrayList<>();
		boolean loop = false;
		if (mover.getOwnedTrajectory() != null) {
			loop = mover.getOwnedTrajectory().isLoop();
			for (ControlPoint point : mover.getOwnedTrajectory().getOwnedControlPoints()) {
				double[] centre = centre(point.getFloor(), layout);
				points.add(new Diagram.Waypoint(name(point.getFloor()), point.getTime(),
						centre == null ? null : centre[0], centre == null ? null : centre[1]));
			}
		}
		boolean human = mover instanceof Human;
		Diagram.Route route = null;
		if (mover instanceof Human person && person.getOwnedRoute() != null) {
			loop = person.getOwnedRoute().isLoop();
			route = route(person.getOwnedRoute(), layout);
		}
		return new Diagram.Mover(mover.getName(), human ? "human" : "dynamic",
				footprint(mover.getType(), defaults, human ? "Human" : null), points, loop, route);
	}

	private static Diagram.Route route(Route route, FloorLayout layout) {
		List<Diagram.Stop> stops = new ArrayList<>();
		for (RouteStop stop : route.getOwnedStops()) {
			double[] centre = centre(stop.getFloor(), layout);
			stops.add(new Diagram.Stop(name(stop.getFloor()), stop.getWait(), centre == null ? null : centre[0],
					centre == null ? null : centre[1]));
		}
		return new Diagram.Route(stops, route.getSpeed(), route.getStart(),
				route.getBehaviour().getName().toLowerCase(Locale.ROOT));
	}

	private static Diagram.Mission mission(TestCase testCase, FloorLayout layout) {
		org.rei.context.Mission mission = testCase.getOwnedMission();
		if (mission == null) {
			return null;
		}
		List<Diagram.Goal> goals = new ArrayList<>();
		List<Task> tasks = mission.getOwnedTasks();
		for (int i = 0; i < tasks.size(); i++) {
			if (tasks.get(i) instanceof NavigationTask task) {
				double[] centre = layout == null ? null : centre(task.getGoal(), layout);
				goals.add(new Diagram.Goal(i, name(task.getGoal()), task.isSetTimeout() ? task.getTimeout() : null,
						centre == null ? null : centre[0], centre == null ? null : centre[1]));
			}
		}
		return new Diagram.Mission(mission.getName(), mission.getGoalTolerance(), mission.getTaskTimeout(), goals);
	}

	private static Diagram.Monitor monitor(MonitorSpec monitor) {
		return monitor == null ? null
				: new Diagram.Monitor(monitor.getEpsClose(), monitor.getEpsCollision(),
						monitor.getMaxHumanCollisions());
	}

	/** The type's outline; an untyped human is the default catalogue's Human. */
	private static Diagram.Footprint footprint(ObjectType type, Catalogue defaults, String defaultType) {
		ObjectType effective = type != null && !type.eIsProxy() ? type
				: defaultType == null ? null : Catalogues.find(defaults, defaultType).orElse(null);
		if (effective == null) {
			return null;
		}
		if (Polygons.isPolygon(effective) && effective.getVertices().size() >= 3) { // as world.json places it
			double[] b = Polygons.bounds(Polygons.points(effective));
			return new Diagram.Footprint(effective.getName(), "polygon", b[2] - b[0], b[3] - b[1],
					effective.getSizeZ(), effective.getColour(), null,
					new Diagram.Outline("polygon", Polygons.centred(effective)));
		}
		return new Diagram.Footprint(effective.getName(), effective.getShape().getLiteral().toLowerCase(),
				effective.getSizeX(), effective.getSizeY(), effective.getSizeZ(), effective.getColour(),
				description(effective));
	}

	/** A described robot type's file, arguments and lidar link; null for any other type or a file not resolved. */
	private static Diagram.Description description(ObjectType type) {
		if (!(type instanceof RobotType robot) || robot.getDescription() == null) {
			return null;
		}
		Path file = RobotDescriptions.file(robot);
		if (file == null) {
			return null;
		}
		Map<String, String> args = new LinkedHashMap<>();
		int count = Math.min(robot.getDescriptionArgNames().size(), robot.getDescriptionArgValues().size());
		for (int i = 0; i < count; i++) {
			args.put(robot.getDescriptionArgNames().get(i), robot.getDescriptionArgValues().get(i));
		}
		String lidar = robot.getLidar() == null ? null : robot.getLidar().getLink();
		return new Diagram.Description(file.toString(), args, lidar);
	}

	private static String typeName(ObjectType type, Catalogue defaults, String defaultType) {
		return type != null && !type.eIsProxy() ? type.getName()
				: Catalogues.find(defaults, defaultType).map(ObjectType::getName).orElse(defaultType);
	}

	private static double[] centre(Floor floor, FloorLayout layout) {
		return floor != null && layout.cellOf(floor).isPresent() ? layout.centreOf(floor) : null;
	}

	private static String name(Floor floor) {
		return floor == null || floor.eIsProxy() ? null : floor.getName();
	}

	private static ResourceSet resourceSet(TestCase testCase) {
		ResourceSet resourceSet = testCase.eResource() == null ? null : testCase.eResource().getResourceSet();
		return resourceSet != null ? resourceSet : new org.eclipse.emf.ecore.resource.impl.ResourceSetImpl();
	}
}
