/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.monitor.config.CaseReader;
import org.rei.monitor.config.World;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A POLYGON object's footprint is its polygon, concave as written, placed and turned about its pose (the bounding
 * box's centre): a point in an L's open corner is measured to the L's inner edges, not inside its bounding box.
 */
class PolygonObjectFootprintTest {

	private static final double EPS = 1e-9;
	/** An L about its bounding box's centre: 1.6 x 1.4, the open corner at the top right. */
	private static final double[][] L = { { -0.8, -0.7 }, { 0.8, -0.7 }, { 0.8, -0.1 }, { -0.2, -0.1 }, { -0.2, 0.7 },
			{ -0.8, 0.7 } };

	@Test
	void theOpenCornerIsOutsideAndTurnsWithTheObject() {
		Footprint probe = Footprint.place("p", Shape.circle(0.1), 0.4, 0.4, 0); // in the open corner
		// nearest: the inner corner (-0.2, -0.1) ... (0.8, -0.1) edge, 0.5 below; (-0.2, ..) edge 0.6 left
		assertEquals(0.5 - 0.05, FootprintDistance.between(Footprint.place("l", Shape.polygon(L), 0, 0, 0), probe), EPS);
		// turned a quarter about its centre, the open corner is at the top left: the probe at (-0.4, 0.4)
		Footprint turned = Footprint.place("l", Shape.polygon(L), 0, 0, Math.PI / 2);
		assertEquals(0.5 - 0.05, FootprintDistance.between(turned, Footprint.place("p", Shape.circle(0.1), -0.4, 0.4, 0)),
				EPS);
		assertEquals(0.0, FootprintDistance.between(turned, probe), EPS); // its arm now covers (0.4, 0.4)
	}

	@Test
	void worldJsonGivesTheObjectItsPolygon(@TempDir Path dir) throws IOException {
		ObjectMapper json = new ObjectMapper();
		ObjectNode world = (ObjectNode) json.readTree(Files.readAllBytes(
				Path.of("src/test/resources/cases/room/world.json")));
		for (var o : world.get("objects")) {
			if (o.get("name").asText().equals("table1")) {
				ObjectNode desk = (ObjectNode) o;
				desk.put("shape", "POLYGON");
				ArrayNode points = desk.putObject("footprint").put("type", "polygon").putArray("points");
				for (double[] p : L) {
					points.addArray().add(p[0]).add(p[1]);
				}
			}
		}
		Files.write(dir.resolve("world.json"), json.writeValueAsBytes(world));
		Files.copy(Path.of("src/test/resources/cases/room/monitor.json"), dir.resolve("monitor.json"));
		World read = CaseReader.readFolder(dir).world();
		World.WorldObject table = read.objects().stream().filter(o -> o.name().equals("table1")).findFirst()
				.orElseThrow();
		assertEquals(Shape.Kind.POLYGON, table.footprint().kind());
		assertEquals(6, table.footprint().points().length);
		assertEquals(1.6, table.footprint().sizeX(), EPS);
		World.WorldObject human = read.objects().stream().filter(o -> o.name().equals("h1")).findFirst().orElseThrow();
		assertEquals(null, human.footprint());
	}
}
