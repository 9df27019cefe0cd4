/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.model;

import java.util.HashMap;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceImpl;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.BuildingBlock;
import org.rei.context.ContextFactory;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.PhysicalObject;
import org.rei.context.Robot;
import org.rei.context.SimulationObject;
import org.rei.monitor.config.MonitorSpec;
import org.rei.monitor.config.World;
import org.rei.monitor.wire.MissionMessage;
import org.rei.monitor.wire.ObjectState;
import org.rei.monitor.wire.RobotState;
import org.rei.monitor.wire.StateMessage;
import org.rei.runtime.ConcreteEnvironment;
import org.rei.runtime.ConcreteObject;
import org.rei.runtime.MissionState;
import org.rei.runtime.NavigationState;
import org.rei.runtime.Pose;
import org.rei.runtime.RobotDescription;
import org.rei.runtime.RuntimeFactory;
import org.rei.runtime.RuntimeModel;
import org.rei.runtime.TaskState;
import org.rei.runtime.TaskStatus;
import org.rei.runtime.Twist;
import org.rei.vepl.runtime.MissionEvent;

/**
 * Keeps the EMF runtime model (thesis 5.1.5.1) in step with the wire: the concrete environment is set up from
 * world.json and updated from every state message; the abstract environment is rebuilt by inverting the
 * generator's mapping (floors from their cells, each object on the floor under its centre, types from the
 * catalogue) and follows the objects that move; the robot description takes odometry, laser and navigation state;
 * the mission state follows the mission topic.
 */
public final class RuntimeModelUpdater {

	private static final RuntimeFactory RT = RuntimeFactory.eINSTANCE;
	private static final ContextFactory CTX = ContextFactory.eINSTANCE;

	private final RuntimeModel model;
	private final Catalogue catalogue;
	private final Resource resource;
	private final FloorGrid grid;
	private final Map<String, ConcreteObject> concrete = new HashMap<>();
	private final Map<String, PhysicalObject> abstracts = new HashMap<>();
	private final Map<String, BuildingBlock> blocks = new HashMap<>();
	private ConcreteObject robotBody;
	private Robot abstractRobot;

	private RuntimeModelUpdater(String runId, World world, MonitorSpec spec) {
		catalogue = CatalogueBuilder.build(spec);
		CatalogueBuilder.addPolygons(catalogue, world);
		model = RT.createRuntimeModel();
		model.setRunId(runId);
		grid = new FloorGrid(world.floorSize());
		model.setOwnedConcreteEnvironment(concreteEnvironment(world));
		model.setOwnedAbstractEnvironment(abstractEnvironment(world));
		model.setOwnedRobot(robotDescription(world));
		MissionState mission = RT.createMissionState();
		model.setOwnedMissionState(mission);
		resource = new XMIResourceImpl(URI.createURI("rei-runtime.xmi"));
		resource.getContents().add(model);
		resource.getContents().add(catalogue);
	}

	/** The runtime model of a run before its first message: world.json as generated. */
	public static RuntimeModelUpdater create(String runId, World world, MonitorSpec spec) {
		return new RuntimeModelUpdater(runId, world, spec);
	}

	public RuntimeModel model() {
		return model;
	}

	/** The resource holding the model and the run's catalogue (for XMI snapshots). */
	public Resource resource() {
		return resource;
	}

	private ConcreteEnvironment concreteEnvironment(World world) {
		ConcreteEnvironment env = RT.createConcreteEnvironment();
		env.setName(world.environment());
		env.setFloorSize(world.floorSize());
		for (World.WorldObject o : world.objects()) {
			ConcreteObject c = concreteObject(o.name(), o.category(), o.type(), o.size(), o.pose());
			env.getOwnedObjects().add(c);
			concrete.put(o.name(), c);
		}
		World.WorldRobot r = world.robot();
		robotBody = concreteObject(r.name(), "ROBOT", r.type(), r.size(), r.pose());
		env.getOwnedObjects().add(robotBody);
		concrete.put(r.name(), robotBody);
		return env;
	}

	private ConcreteObject concreteObject(String name, String category, String type, double[] size, double[] pose) {
		ConcreteObject c = RT.createConcreteObject();
		c.setName(name);
		ObjectCategory cat = ObjectCategory.get(category);
		if (cat != null) {
			c.setCategory(cat);
		}
		Catalogues.find(catalogue, type).ifPresent(c::setType);
		c.setSizeX(size[0]);
		c.setSizeY(size[1]);
		c.setSizeZ(size[2]);
		Pose p = RT.createPose();
		p.setX(pose[0]);
		p.setY(pose[1]);
		p.setZ(pose[2]);
		p.setYaw(pose[3]);
		c.setPose(p);
		c.setTwist(RT.createTwist());
		return c;
	}

	private Environment abstractEnvironment(World world) {
		Environment env = CTX.createEnvironment();
		env.setName(world.environment());
		env.setFloorSize(world.floorSize());
		Map<String, Floor> floors = new HashMap<>();
		for (World.FloorCell f : world.floors()) {
			Floor floor = CTX.createFloor();
			floor.setName(f.name());
			typed(floor, "Floor");
			floors.put(f.name(), floor);
			blocks.put(f.name(), floor);
			grid.put(f.i(), f.j(), floor);
			env.getOwnedBlocks().add(floor);
		}
		for (World.WorldObject o : world.objects()) {
			if ("WALL".equals(o.category())) {
				org.rei.context.Wall wall = CTX.createWall();
				wall.setName(o.name());
				typed(wall, o.type());
				blocks.put(o.name(), wall);
				env.getOwnedBlocks().add(wall);
			}
		}
		for (World.FloorCell f : world.floors()) {
			Floor floor = floors.get(f.name());
			floor.setTop(blocks.get(f.top() == null ? "" : f.top()));
			floor.setRight(blocks.get(f.right() == null ? "" : f.right()));
			floor.setBottom(blocks.get(f.bottom() == null ? "" : f.bottom()));
			floor.setLeft(blocks.get(f.left() == null ? "" : f.left()));
		}
		for (World.WorldObject o : world.objects()) {
			PhysicalObject p = switch (o.category()) {
			case "STATIC" -> CTX.createStaticObject();
			case "DYNAMIC" -> CTX.createDynamicObject();
			case "HUMAN" -> CTX.createHuman();
			default -> null;
			};
			if (p != null) {
				p.setName(o.name());
				typed(p, o.type());
				p.setYaw(o.pose()[3]);
				p.setFloor(grid.floorAt(o.pose()[0], o.pose()[1]));
				abstracts.put(o.name(), p);
				env.getOwnedObjects().add(p);
			}
		}
		World.WorldRobot r = world.robot();
		abstractRobot = CTX.createRobot();
		abstractRobot.setName(r.name());
		typed(abstractRobot, r.type());
		abstractRobot.setYaw(r.pose()[3]);
		abstractRobot.setFloor(grid.floorAt(r.pose()[0], r.pose()[1]));
		env.setOwnedRobot(abstractRobot);
		for (Map.Entry<String, ConcreteObject> e : concrete.entrySet()) {
			Pose p = e.getValue().getPose();
			e.getValue().setStandsOn(grid.floorAt(p.getX(), p.getY()));
		}
		return env;
	}

	private void typed(SimulationObject o, String type) {
		Catalogues.find(catalogue, type).ifPresent(o::setType);
	}

	private RobotDescription robotDescription(World world) {
		RobotDescription r = RT.createRobotDescription();
		r.setName(world.robot().name());
		r.setBody(robotBody);
		Pose odom = RT.createPose();
		odom.setX(world.robot().pose()[0]);
		odom.setY(world.robot().pose()[1]);
		odom.setYaw(world.robot().pose()[3]);
		r.setOdometry(odom);
		r.setLaserMin(Double.POSITIVE_INFINITY);
		r.setLaserClearance(Double.POSITIVE_INFINITY);
		return r;
	}

	/** The laser's distance to the footprint as the monitor judges it (it knows the robot's shape). */
	public void applyLaserClearance(double clearance) {
		model.getOwnedRobot().setLaserClearance(clearance);
	}

	/** Applies one decoded state message: poses, twists, floors, robot belief and sensors. */
	public void applyState(StateMessage m) {
		model.setTime(m.t());
		for (ObjectState o : m.objects()) {
			ConcreteObject c = concrete.get(o.name());
			if (c == null || (c.getPose().getX() == o.x() && c.getPose().getY() == o.y()
					&& c.getPose().getYaw() == o.yaw() && c.getTwist().getVx() == o.vx() && c.getTwist().getVy() == o.vy()
					&& c.getTwist().getWz() == o.wz())) {
				continue; // unknown bodies have no footprint (counted by the monitor); resent statics did not move
			}
			move(c, o.x(), o.y(), o.z(), o.yaw(), o.vx(), o.vy(), o.wz());
			PhysicalObject a = abstracts.get(o.name());
			if (a != null) {
				a.setYaw(o.yaw());
				Floor f = c.getStandsOn();
				if (a.getFloor() != f) {
					a.setFloor(f);
				}
			}
		}
		RobotState r = m.robot();
		move(robotBody, r.x(), r.y(), r.z(), r.yaw(), r.vx(), r.vy(), r.wz());
		abstractRobot.setYaw(r.yaw());
		if (abstractRobot.getFloor() != robotBody.getStandsOn()) {
			abstractRobot.setFloor(robotBody.getStandsOn());
		}
		RobotDescription d = model.getOwnedRobot();
		if (r.odom() != null) {
			d.getOdometry().setX(r.odom()[0]);
			d.getOdometry().setY(r.odom()[1]);
			d.getOdometry().setYaw(r.odom()[2]);
		}
		if (r.hasLaser()) {
			d.setLaserMin(r.laserMin());
		}

		if (r.laserRanges() != null) {
			d.getLaserRanges().clear();
			for (double v : r.laserRanges()) {
				d.getLaserRanges().add(v);
			}
		}
		if (r.navState() != null) {
			NavigationState nav = NavigationState.get(r.navState());
			if (nav != null) {
				d.setNavigationState(nav);
			}
		}
	}

	private void move(ConcreteObject c, double x, double y, double z, double yaw, double vx, double vy, double wz) {
		Pose p = c.getPose();
		p.setX(x);
		p.setY(y);
		p.setZ(z);
		p.setYaw(yaw);
		Twist t = c.getTwist();
		t.setVx(vx);
		t.setVy(vy);
		t.setWz(wz);
		Floor f = grid.floorAt(x, y);
		if (c.getStandsOn() != f) {
			c.setStandsOn(f);
		}
	}

	/** Applies one mission event to the mission state. */
	public void applyMission(MissionMessage m) {
		if (MissionEvent.isFault(m.event())) {
			return; // a fault window's edge: no mission or task state changes, the patterns see it as an event
		}
		MissionState s = model.getOwnedMissionState();
		switch (m.event()) {
		case MissionEvent.BEGIN -> s.setBegun(true);
		case MissionEvent.END -> s.setEnded(true);
		default -> {
			TaskState task = task(s, m.taskIndex());
			if (m.goal() != null) {
				Pose g = RT.createPose();
				g.setX(m.goal()[0]);
				g.setY(m.goal()[1]);
				g.setYaw(m.goal()[2]);
				task.setGoal(g);
			}
			task.setStatus(switch (m.event()) {
			case MissionEvent.TASK_START -> TaskStatus.ACTIVE;
			case MissionEvent.TASK_SUCCESS -> TaskStatus.SUCCEEDED;
			default -> TaskStatus.FAILED;
			});
			if (m.reason() != null) {
				task.setReason(m.reason());
			}
		}
		}
	}

	private static TaskState task(MissionState s, int index) {
		for (TaskState t : s.getOwnedTasks()) {
			if (t.getIndex() == index) {
				return t;
			}
		}
		TaskState t = RT.createTaskState();
		t.setIndex(index);
		t.setStatus(TaskStatus.PENDING);
		s.getOwnedTasks().add(t);
		return t;
	}

	/** The concrete object named {@code name}, or null. */
	public ConcreteObject object(String name) {
		return concrete.get(name);
	}

	/** The abstract object named {@code name} (furniture, carts, humans), or null. */
	public PhysicalObject abstractObject(String name) {
		return abstracts.get(name);
	}

	public Robot abstractRobot() {
		return abstractRobot;
	}
}
