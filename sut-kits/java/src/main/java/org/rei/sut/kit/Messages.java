/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The payloads of docs/sut.md to and from records. Numbers are read leniently (an integer where a float is due, as
 * a JSON transport delivers); anything missing or of the wrong kind is a protocol error naming the field.
 */
final class Messages {

	static final int PROTOCOL = 1;

	private Messages() {
	}

	/** A tick as received; {@code scan} is null when the tick carries none. */
	record TickMessage(long tick, double t, Pose odom, Twist twist, Scan scan) {
	}

	static Session session(JsonNode m) {
		String what = "hello's answer";
		int protocol = (int) integer(m, "protocol", what);
		if (protocol != PROTOCOL) {
			throw malformed(what, "protocol " + protocol + " is not supported by this kit (" + PROTOCOL + ")");
		}
		JsonNode robot = object(m, "robot", what);
		JsonNode lidar = object(robot, "lidar", what + ": robot");
		double[] footprint = numbers(robot, "footprint", 2, what + ": robot");
		// drive and max_lateral came with holonomic robots: a simulation without them has a differential one
		JsonNode drive = robot.get("drive");
		Session.Robot r = new Session.Robot(text(robot, "name", what), footprint[0], footprint[1],
				number(robot, "max_linear", what), number(robot, "max_angular", what),
				new Session.Lidar((int) integer(lidar, "beams", what), number(lidar, "range_min", what),
						number(lidar, "range_max", what), number(lidar, "rate", what), orZero(lidar, "x", what),
						orZero(lidar, "y", what), orZero(lidar, "yaw", what)),
				drive == null ? Session.DRIVES.get(0) : text(robot, "drive", what),
				robot.has("max_lateral") ? number(robot, "max_lateral", what) : 0.0, outline(robot.get("outline")));
		String clock = text(m, "clock", what);
		Session.Clock c = switch (clock) {
		case "lockstep" -> Session.Clock.LOCKSTEP;
		case "realtime" -> Session.Clock.REALTIME;
		default -> throw malformed(what, "unknown clock '" + clock + "'");
		};
		return new Session(protocol, text(m, "run_id", what), c, number(m, "control_rate", what),
				number(m, "deadline", what), pose(m, "start", what), r, (int) integer(m, "goals", what),
				map(m.get("map")));
	}

	private static Session.Outline outline(JsonNode outline) {
		if (outline == null || outline.isNull()) {
			return null;
		}
		String what = "hello's answer: robot: outline";
		String type = text(outline, "type", what);
		if (type.equals(Session.Outline.TYPES.get(1))) {
			return new Session.Outline(List.of(), number(outline, "x", what), number(outline, "y", what),
					number(outline, "radius", what));
		}
		if (!type.equals(Session.Outline.TYPES.get(0))) {
			throw malformed(what, "unknown type '" + type + "'");
		}
		JsonNode list = outline.get("points");
		if (list == null || !list.isArray() || list.size() < 3) {
			throw malformed(what, "'points' is not a list of at least 3 points");
		}
		List<double[]> points = new ArrayList<>();
		for (JsonNode point : list) {
			points.add(numbers(point, 2, what + ": points"));
		}
		return new Session.Outline(List.copyOf(points), 0.0, 0.0, 0.0);
	}

	private static Session.StaticMap map(JsonNode map) {
		if (map == null || map.isNull()) {
			return null;
		}
		String what = "hello's answer: map";
		double[] b = numbers(map, "bounds", 4, what);
		JsonNode list = map.get("obstacles");
		if (list == null || !list.isArray()) {
			throw malformed(what, "'obstacles' is not a list");
		}
		List<Session.Obstacle> obstacles = new ArrayList<>();
		for (JsonNode o : list) {
			double[] v = numbers(o, 5, what + ": obstacle");
			obstacles.add(new Session.Obstacle(v[0], v[1], v[2], v[3], v[4]));
		}
		JsonNode occupancy = map.get("occupancy");
		if (occupancy != null && !occupancy.isNull() && !occupancy.isTextual()) {
			throw malformed(what, "'occupancy' is not a string");
		}
		return new Session.StaticMap(b[0], b[1], b[2], b[3], List.copyOf(obstacles),
				occupancy == null || occupancy.isNull() ? null : occupancy.asText());
	}

	static Goal goal(JsonNode m) {
		String what = "goal";
		return new Goal((int) integer(m, "goal_id", what), number(m, "t", what), pose(m, "pose", what),
				number(m, "tolerance", what));
	}

	/** The goal id of a cancel. */
	static int cancel(JsonNode m) {
		return (int) integer(m, "goal_id", "cancel");
	}

	/** The reason of an end, "" if it has none. */
	static String end(JsonNode m) {
		JsonNode reason = m == null ? null : m.get("reason");
		return reason == null || reason.isNull() ? "" : reason.asText();
	}

	static TickMessage tick(JsonNode m) {
		String what = "tick";
		JsonNode odom = object(m, "odom", what);
		JsonNode list = field(odom, "twist", what + ": odom");
		// [v, w], or a holonomic robot's [v, w, vy]
		double[] twist = numbers(list, list.isArray() && list.size() == 3 ? 3 : 2, what + ": odom: twist");
		JsonNode scan = m.get("scan");
		return new TickMessage(integer(m, "tick", what), number(m, "t", what), pose(odom, "pose", what + ": odom"),
				new Twist(twist[0], twist[1], twist.length == 3 ? twist[2] : 0.0),
				scan == null || scan.isNull() ? null : scan(scan));
	}

	static Scan scan(JsonNode m) {
		String what = "tick: scan";
		JsonNode list = m.get("ranges");
		if (list == null || !list.isArray()) {
			throw malformed(what, "'ranges' is not a list");
		}
		double[] ranges = new double[list.size()];
		for (int i = 0; i < ranges.length; i++) {
			JsonNode r = list.get(i);
			if (r.isNull()) {
				ranges[i] = Double.POSITIVE_INFINITY; // JSON cannot write inf; some encoders write null instead
			} else if (r.isNumber()) {
				ranges[i] = r.asDouble();
			} else {
				throw malformed(what, "ranges[" + i + "] is not a number");
			}
		}
		return new Scan(number(m, "t", what), number(m, "angle_min", what), number(m, "angle_max", what),
				number(m, "angle_increment", what), number(m, "scan_time", what), number(m, "range_min", what),
				number(m, "range_max", what), ranges);
	}

	/** {@code {tick, v, w, vy?}}: an integer and floats; vy only when it is not 0 (a holonomic robot's). */
	static ObjectNode command(long tick, Command c) {
		ObjectNode m = JsonNodeFactory.instance.objectNode();
		m.put("tick", tick);
		m.put("v", c.v());
		m.put("w", c.w());
		if (c.vy() != 0.0) {
			m.put("vy", c.vy());
		}
		return m;
	}

	/** {@code {goal_id, status, text?}}. */
	static ObjectNode status(int goalId, GoalStatus status, String text) {
		ObjectNode m = JsonNodeFactory.instance.objectNode();
		m.put("goal_id", goalId);
		m.put("status", status.name());
		if (text != null) {
			m.put("text", text);
		}
		return m;
	}

	private static JsonNode field(JsonNode m, String name, String what) {
		if (m == null || !m.isObject()) {
			throw malformed(what, "not a map");
		}
		JsonNode v = m.get(name);
		if (v == null || v.isNull()) {
			throw malformed(what, "'" + name + "' is missing");
		}
		return v;
	}

	private static JsonNode object(JsonNode m, String name, String what) {
		JsonNode v = field(m, name, what);
		if (!v.isObject()) {
			throw malformed(what, "'" + name + "' is not a map");
		}
		return v;
	}

	private static String text(JsonNode m, String name, String what) {
		JsonNode v = field(m, name, what);
		if (!v.isTextual()) {
			throw malformed(what, "'" + name + "' is not a string");
		}
		return v.asText();
	}

	/** A field that came later (a lidar's place on the robot): 0 from a simulation that does not send it. */
	private static double orZero(JsonNode m, String name, String what) {
		return m.has(name) ? number(m, name, what) : 0.0;
	}

	private static double number(JsonNode m, String name, String what) {
		JsonNode v = field(m, name, what);
		if (!v.isNumber()) {
			throw malformed(what, "'" + name + "' is not a number");
		}
		return v.asDouble();
	}

	/** An integer; a float with an integral value is one too (JSON transports may write 3.0). */
	private static long integer(JsonNode m, String name, String what) {
		JsonNode v = field(m, name, what);
		if (v.isIntegralNumber() && v.canConvertToLong()) {
			return v.asLong();
		}
		if (v.isNumber() && v.asDouble() == Math.rint(v.asDouble()) && Math.abs(v.asDouble()) < 0x1p53) {
			return (long) v.asDouble();
		}
		throw malformed(what, "'" + name + "' is not an integer");
	}

	private static Pose pose(JsonNode m, String name, String what) {
		double[] v = numbers(m, name, 3, what);
		return new Pose(v[0], v[1], v[2]);
	}

	private static double[] numbers(JsonNode m, String name, int n, String what) {
		return numbers(field(m, name, what), n, what + ": " + name);
	}

	private static double[] numbers(JsonNode list, int n, String what) {
		if (!list.isArray() || list.size() != n) {
			throw malformed(what, "not a list of " + n + " numbers");
		}
		double[] v = new double[n];
		for (int i = 0; i < n; i++) {
			if (!list.get(i).isNumber()) {
				throw malformed(what, "not a list of " + n + " numbers");
			}
			v[i] = list.get(i).asDouble();
		}
		return v;
	}

	static SutException malformed(String what, String detail) {
		return new SutException(SutClient.EXIT_CONNECTION,
				String.format(Locale.ROOT, "malformed %s from the simulation: %s", what, detail));
	}
}
