/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.config;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.rei.monitor.geometry.Shape;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Reads world.json and monitor.json, from a case folder ({@code --case DIR}) or from the trees the {@code config}
 * RPC returns. Readers reject a format they do not know (docs/artifacts.md).
 */
public final class CaseReader {

	private static final ObjectMapper JSON = new ObjectMapper();

	private CaseReader() {
	}

	/** The world and monitor specification of a generated case folder. */
	public static Case readFolder(Path dir) throws IOException {
		JsonNode world = JSON.readTree(Files.readAllBytes(dir.resolve("world.json")));
		JsonNode monitor = JSON.readTree(Files.readAllBytes(dir.resolve("monitor.json")));
		return new Case(world(world), monitor(monitor));
	}

	/** A world and monitor specification as one value. */
	public record Case(World world, MonitorSpec monitor) {
	}

	public static World world(JsonNode n) {
		format(n, "rei-world/1");
		List<World.FloorCell> floors = new ArrayList<>();
		for (JsonNode f : n.path("floors")) {
			floors.add(new World.FloorCell(f.path("name").asText(), f.path("cell").path(0).asInt(),
					f.path("cell").path(1).asInt(), text(f, "top"), text(f, "right"), text(f, "bottom"),
					text(f, "left")));
		}
		List<World.WorldObject> objects = new ArrayList<>();
		for (JsonNode o : n.path("objects")) {
			objects.add(new World.WorldObject(o.path("name").asText(), o.path("category").asText(),
					o.path("type").asText(), o.path("shape").asText("BOX"), doubles(o.path("size"), 3),
					doubles(o.path("pose"), 4), text(o, "floor"), footprint(o.path("footprint"))));
		}
		JsonNode r = n.path("robot");
		World.WorldRobot robot = new World.WorldRobot(r.path("name").asText(), r.path("type").asText(),
				r.path("shape").asText("BOX"), doubles(r.path("size"), 3), doubles(r.path("pose"), 4), text(r, "floor"),
				r.path("lidar").path("rangeMin").asDouble(0), r.path("lidar").path("rangeMax").asDouble(
						Double.POSITIVE_INFINITY), footprint(r.path("footprint")));
		return new World(text(n, "testcase"), text(n, "environment"), n.path("floorSize").asDouble(1.0), floors,
				objects, robot);
	}

	/** world.json's robot.footprint.type: polygon, circle (contract/vocabulary.json footprints). */
	public static final List<String> FOOTPRINT_TYPES = List.of("polygon", "circle");

	/**
	 * world.json's footprint of a robot read from its description (a convex polygon or a circle in the robot's
	 * frame) or of a POLYGON object (a simple polygon, convex or not, about its pose) (rei.artifacts.world);
	 * {@code null} for a box robot and every other object.
	 */
	static Shape footprint(JsonNode f) {
		if (f.isMissingNode() || f.isNull()) {
			return null;
		}
		String type = f.path("type").asText();
		if (FOOTPRINT_TYPES.get(1).equals(type)) {
			return Shape.circle(f.path("x").asDouble(), f.path("y").asDouble(), f.path("radius").asDouble());
		}
		if (!FOOTPRINT_TYPES.get(0).equals(type)) {
			throw new IllegalArgumentException("world.json footprint.type must be one of " + FOOTPRINT_TYPES
					+ ", got " + type);
		}
		List<double[]> points = new ArrayList<>();
		for (JsonNode p : f.path("points")) {
			points.add(new double[] { p.path(0).asDouble(), p.path(1).asDouble() });
		}
		return Shape.polygon(points.toArray(double[][]::new));
	}

	public static MonitorSpec monitor(JsonNode n) {
		format(n, "rei-monitor/1");
		Map<String, String> topics = new LinkedHashMap<>();
		n.path("topics").fields().forEachRemaining(e -> topics.put(e.getKey(), e.getValue().asText()));
		List<MonitorSpec.CatalogueEntry> catalogue = new ArrayList<>();
		for (JsonNode c : n.path("catalogue")) {
			catalogue.add(new MonitorSpec.CatalogueEntry(c.path("name").asText(), c.path("category").asText(),
					c.path("shape").asText("BOX"), doubles(c.path("size"), 3), c.path("mass").asDouble(0)));
		}
		JsonNode th = n.path("thresholds");
		double collision = threshold(th, "collision");
		double close = threshold(th, "close");
		if (close <= collision) { // 0 < collision < close, as the DSL and rei.artifacts.monitor require
			throw new IllegalArgumentException("monitor.json thresholds.close must be above thresholds.collision ("
					+ collision + " m), got " + close);
		}
		return new MonitorSpec(text(n, "testcase"), text(n, "robot"), close, collision, topics, catalogue);
	}

	/** A threshold in metres: present, finite and above 0 (a missing one is an error, never a default). */
	private static double threshold(JsonNode thresholds, String name) {
		JsonNode v = thresholds.get(name);
		if (v == null || !v.isNumber() || !Double.isFinite(v.asDouble()) || v.asDouble() <= 0) {
			throw new IllegalArgumentException("monitor.json thresholds." + name + " must be a number of metres above 0, got "
					+ (v == null ? "nothing" : v.toString()));
		}
		return v.asDouble();
	}

	private static void format(JsonNode n, String expected) {
		String format = n.path("format").asText("");
		if (!expected.equals(format)) {
			throw new IllegalArgumentException("expected format " + expected + ", got '" + format + "'");
		}
	}

	private static String text(JsonNode n, String field) {
		JsonNode v = n.get(field);
		return v == null || v.isNull() ? null : v.asText();
	}

	private static double[] doubles(JsonNode array, int n) {
		double[] out = new double[n];
		for (int i = 0; i < n; i++) {
			out[i] = array.path(i).asDouble(0);
		}
		return out;
	}
}
