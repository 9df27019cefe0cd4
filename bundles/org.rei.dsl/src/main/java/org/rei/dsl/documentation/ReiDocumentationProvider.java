/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.documentation;

import java.util.List;
import java.util.Locale;
import java.util.Optional;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.rei.catalogue.Lidar;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.util.Polygons;
import org.rei.catalogue.RobotType;
import org.rei.context.Behaviour;
import org.rei.context.ControlPoint;
import org.rei.context.Crowd;
import org.rei.context.Environment;
import org.rei.context.Floor;
import org.rei.context.Group;
import org.rei.context.Human;
import org.rei.context.MonitorSpec;
import org.rei.context.Route;
import org.rei.context.RouteStop;
import org.rei.context.SimulationObject;
import org.rei.context.StaticObject;
import org.rei.context.Trajectory;
import org.rei.context.Wall;
import org.rei.context.layout.FloorLayout;
import org.rei.context.people.WalkingSpeed;
import org.rei.dsl.derived.RoomDesugaring;

/**
 * What an editor's hover shows (Markdown; the language server sends it as the hover's contents): where a floor
 * is, what an object type measures and weighs, what a robot type can do, what the monitor's thresholds mean, when
 * a human passes where (or, on a route, where it goes, how fast and how it behaves towards the robot), who a crowd
 * or a group is. Derived from the model and the catalogue, never stored text.
 */
public class ReiDocumentationProvider implements IEObjectDocumentationProvider {

	@Override
	public String getDocumentation(EObject o) {
		if (o instanceof Floor f) {
			return floor(f);
		}
		if (o instanceof Wall w) {
			return "**Wall " + w.getName() + "**" + type(w.getType());
		}
		if (o instanceof RobotType r) {
			return robotType(r);
		}
		if (o instanceof ObjectType t) {
			return objectType(t);
		}
		if (o instanceof Human h) {
			return human(h);
		}
		if (o instanceof Crowd c) {
			return crowd(c);
		}
		if (o instanceof SimulationObject s) {
			String where = s instanceof StaticObject so && so.getFloor() != null ? " on " + floorLine(so.getFloor()) : "";
			return "**" + s.getName() + "**" + where + type(s.getType());
		}
		if (o instanceof MonitorSpec m) {
			return monitor(m);
		}
		return null;
	}

	private static String floor(Floor f) {
		return "**Floor " + f.getName() + "**: " + floorLine(f);
	}

	/** "x 2..3 m, y 1..2 m, centre (2.50, 1.50)" from the room's layout, or why it has no place. */
	static String floorLine(Floor f) {
		if (!(f.eContainer() instanceof Environment env)) {
			return "not in a room";
		}
		FloorLayout layout = RoomDesugaring.layoutOf(env);
		Optional<?> cell = layout.cellOf(f);
		if (cell.isEmpty()) {
			return "no place in the room's layout (see the layout errors)";
		}
		double[] c = layout.centreOf(f);
		double h = layout.floorSize() / 2;
		return String.format(Locale.ROOT, "x %s..%s m, y %s..%s m, centre (%.2f, %.2f)", num(c[0] - h), num(c[0] + h),
				num(c[1] - h), num(c[1] + h), c[0], c[1]);
	}

	private static String type(ObjectType t) {
		return t == null || t.eIsProxy() ? "" : "\n\n" + objectType(t);
	}

	private static String objectType(ObjectType t) {
		if (Polygons.isPolygon(t) && t.getVertices().size() >= 3) { // its bounding box and area, its vertices' count
			double[][] p = Polygons.points(t);
			double[] b = Polygons.bounds(p);
			return String.format(Locale.ROOT, "**%s** (%s): polygon of %d vertices, %s m^2, %s x %s m, %s m high, "
					+ "%s kg", t.getName(), t.getCategory().getLiteral(), p.length,
					num(Math.round(Math.abs(Polygons.doubleArea(p)) / 2 * 1e4) / 1e4),
					num(Math.round((b[2] - b[0]) * 1e6) / 1e6), num(Math.round((b[3] - b[1]) * 1e6) / 1e6),
					num(t.getSizeZ()), num(t.getMass()));
		}
		return String.format(Locale.ROOT, "**%s** (%s): %s %s x %s x %s m, %s kg", t.getName(),
				t.getCategory().getLiteral(), t.getShape().getLiteral().toLowerCase(Locale.ROOT), num(t.getSizeX()),
				num(t.getSizeY()), num(t.getSizeZ()), num(t.getMass()))
				+ (t.isSetWalkingSpeed() ? "; walks at " + speed(WalkingSpeed.of(t)) + " m/s" : "");
	}

	private static String robotType(RobotType r) {
		StringBuilder b = new StringBuilder(objectType(r));
		b.append(String.format(Locale.ROOT, "; at most %s m/s and %s rad/s", num(r.getMaxLinearVelocity()),
				num(r.getMaxAngularVelocity())));
		Lidar l = r.getLidar();
		if (l != null) {
			b.append(String.format(Locale.ROOT, "; lidar %d beams, %s..%s m, %s Hz", l.getBeams(), num(l.getRangeMin()),
					num(l.getRangeMax()), num(l.getRate())));
		}
		return b.toString();
	}

	private static String human(Human h) {
		StringBuilder b = new StringBuilder(h instanceof Group g
				? "**Group " + g.getName() + "**, " + g.getCount() + " people (" + g.getName() + "_1 leads, "
						+ members(g.getName(), 2, g.getCount()) + " keep near it)"
				: "**Human " + h.getName() + "**");
		Trajectory t = h.getOwnedTrajectory();
		if (t != null) {
			b.append(t.isLoop() ? ", walking in a loop (Catmull-Rom through the points):" : ", walking once:");
			for (ControlPoint p : t.getOwnedControlPoints()) {
				if (p.getFloor() != null && !p.getFloor().eIsProxy()) {
					b.append("\n- at ").append(num(p.getTime())).append(" s on ").append(p.getFloor().getName())
							.append(": ").append(floorLine(p.getFloor()));
				}
			}
		}
		Route r = h.getOwnedRoute();
		if (r != null) {
			b.append(", walking a route at ").append(speed(WalkingSpeed.of(r, h.getType()))).append(" m/s")
					.append(r.getStart() > 0 ? " from " + num(r.getStart()) + " s" : "")
					.append(r.isLoop() ? " in a loop" : ", then staying at the last stop").append("; ")
					.append(behaviour(r.getBehaviour())).append(':');
			for (RouteStop stop : r.getOwnedStops()) {
				if (stop.getFloor() != null && !stop.getFloor().eIsProxy()) {
					b.append("\n- ").append(stop.getFloor().getName())
							.append(stop.getWait() > 0 ? ", waits " + num(stop.getWait()) + " s" : "").append(": ")
							.append(floorLine(stop.getFloor()));
				}
			}
		}
		return b.append(type(h.getType())).toString();
	}

	private static String crowd(Crowd c) {
		StringBuilder b = new StringBuilder("**Crowd " + c.getName() + "**, ");
		b.append(c.getCount() == 1 ? "1 person (" : c.getCount() + " people (")
				.append(members(c.getName(), 1, c.getCount())).append(") walking at ")
				.append(speed(WalkingSpeed.of(c))).append(" m/s, ")
				.append(c.isSetRate() ? "setting off " + num(c.getRate()) + " a second from " + num(c.getStart()) + " s"
						: "setting off at " + num(c.getStart()) + " s")
				.append(c.isLoop() ? ", back and forth" : ", then staying").append("; ")
				.append(behaviour(c.getBehaviour())).append(":\n- from ").append(names(c.getFrom()))
				.append("\n- to ").append(names(c.getTo()));
		if (c.getQueue() != null) {
			b.append("\n- queueing at ").append(c.getQueue().eIsProxy() ? "?" : c.getQueue().getName())
					.append(" on the way: one passes every ").append(num(c.getQueueEvery())).append(" s");
		}
		return b.append(type(c.getType())).toString();
	}

	/** "g_2 and g_3", "g_2 to g_5", "g_1": the people of a crowd or group from number {@code first} on. */
	private static String members(String name, int first, int count) {
		return count <= first ? name + "_" + first
				: name + "_" + first + (count == first + 1 ? " and " : " to ") + name + "_" + count;
	}

	private static String names(List<Floor> floors) {
		return String.join(", ", floors.stream().map(f -> f.eIsProxy() ? "?" : f.getName()).toList());
	}

	/** "1.2" or "1-1.4". */
	private static String speed(WalkingSpeed speed) {
		return num(speed.speed()) + (speed.isRange() ? "-" + num(speed.speedTo()) : "");
	}

	/** What a behaviour does, as docs/language.md says it. */
	private static String behaviour(Behaviour behaviour) {
		return switch (behaviour) {
		case AVOIDS -> "avoids: steps around the robot and other people";
		case IGNORES -> "ignores: avoids other people but not the robot";
		case CURIOUS -> "curious: comes to the robot, stands in front of it for a while, then goes on";
		case SCARED -> "scared: keeps a wide berth around the robot";
		case BLOCKS -> "blocks: steps into the robot's way";
		};
	}

	private static String monitor(MonitorSpec m) {
		return String.format(Locale.ROOT, """
				**Monitor thresholds** (thesis 5.1.6.2), distances between footprints:
				- FAR: %s m or more
				- CLOSE: below `close` %s m
				- COLLISION: below `collision` %s m, or a contact the simulator reports
				- MISSION_WITH_HUMAN_TRAJECTORY passes with fewer than `maxHumanCollisions` = %d collisions with humans""",
				num(m.getEpsClose()), num(m.getEpsClose()), num(m.getEpsCollision()), m.getMaxHumanCollisions());
	}

	private static String num(double v) {
		return v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v) : String.valueOf(v);
	}
}
