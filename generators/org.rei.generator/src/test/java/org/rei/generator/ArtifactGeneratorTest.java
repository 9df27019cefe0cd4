/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.context.ContextFactory;
import org.rei.context.Floor;
import org.rei.context.MonitorSpec;
import org.rei.context.TestCase;
import org.rei.context.layout.LayoutIssueCodes;
import org.rei.context.layout.LayoutProblem;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

class ArtifactGeneratorTest {

	private static final ObjectMapper JSON = new ObjectMapper();
	private static ArtifactGenerator generator;

	@TempDir
	Path out;

	@BeforeAll
	static void parseTemplatesOnce() {
		generator = new ArtifactGenerator(GeneratorOptions.defaults());
	}

	private JsonNode json(String file) throws IOException {
		return JSON.readTree(out.resolve(file).toFile());
	}

	private Document xml(String file) throws Exception {
		return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(out.resolve(file).toFile());
	}

	private static double[] doubles(JsonNode array) {
		double[] values = new double[array.size()];
		for (int i = 0; i < values.length; i++) {
			values[i] = array.get(i).asDouble();
		}
		return values;
	}

	private static JsonNode named(JsonNode array, String name) {
		for (JsonNode node : array) {
			if (name.equals(node.get("name").asText())) {
				return node;
			}
		}
		throw new AssertionError("no " + name);
	}

	@Test
	void writesTheFiveArtifacts() throws Exception {
		List<Path> files = generator.generate(TestCases.small(), out);

		assertEquals(ArtifactGenerator.ARTIFACTS, files.stream().map(p -> p.getFileName().toString()).toList());
		for (Path file : files) {
			assertTrue(Files.size(file) > 0, file + " is empty");
		}
	}

	@Test
	void worldJsonHasFloorsObjectsAndRobot() throws Exception {
		generator.generate(TestCases.small(), out);
		JsonNode world = json("world.json");

		assertEquals("rei-world/1", world.get("format").asText());
		assertEquals("SmallRoom", world.get("testcase").asText());
		assertEquals("Lab", world.get("environment").asText());
		assertArrayEquals(new double[] { 0, 0, 3, 2 }, doubles(world.get("bounds")));

		JsonNode floors = world.get("floors");
		assertEquals(6, floors.size());
		JsonNode f10 = named(floors, "F_1_0");
		assertArrayEquals(new double[] { 1.5, 0.5 }, doubles(f10.get("center")));
		assertArrayEquals(new double[] { 1, 0 }, doubles(f10.get("cell")));
		assertEquals("F_1_1", f10.get("top").asText());
		assertEquals("F_0_0", f10.get("left").asText(), "declared only by F_0_0: inferred");
		assertEquals("W_1_0_bottom", f10.get("bottom").asText());

		JsonNode objects = world.get("objects");
		assertEquals(6 + 10 + 2, objects.size(), "floors, walls around 3 x 2, table and human");
		assertEquals("F_0_0", objects.get(0).get("name").asText());
		JsonNode floor = named(objects, "F_0_0");
		assertEquals("FLOOR", floor.get("category").asText());
		assertEquals("Floor", floor.get("type").asText());
		assertArrayEquals(new double[] { 0.5, 0.5, -0.005, 0 }, doubles(floor.get("pose")), 1e-9);
		assertEquals(0.0, floor.get("mass").asDouble());

		JsonNode wall = named(objects, "W_0_0_left");
		assertEquals("WALL", wall.get("category").asText());
		assertArrayEquals(new double[] { 0.1, 1.1, 1.0 }, doubles(wall.get("size")), 1e-9);
		assertArrayEquals(new double[] { 0, 0.5, 0.5, 0 }, doubles(wall.get("pose")), 1e-9);
		assertEquals("F_0_0", wall.get("floor").asText());

		JsonNode table = named(objects, "table1");
		assertEquals("STATIC", table.get("category").asText());
		assertArrayEquals(new double[] { 1.5, 0.5, 0.375, 1.570796 }, doubles(table.get("pose")), 1e-9);
		assertEquals(0.0, table.get("mass").asDouble(), "furniture is fixed");
		assertArrayEquals(new double[] { 0, 0, 0 }, doubles(table.get("inertia")));

		JsonNode human = named(objects, "h1");
		assertEquals("HUMAN", human.get("category").asText());
		assertEquals("CYLINDER", human.get("shape").asText());
		assertEquals(70.0, human.get("mass").asDouble());
		// solid cylinder r = 0.25, h = 1.7: m/12 (3 r^2 + h^2) and m/2 r^2
		assertArrayEquals(new double[] { 17.952083, 17.952083, 2.1875 }, doubles(human.get("inertia")), 1e-9);
		assertArrayEquals(new double[] { 224 / 255.0, 172 / 255.0, 105 / 255.0, 1 }, doubles(human.get("colour")), 1e-6);

		JsonNode robot = world.get("robot");
		assertEquals("tb3", robot.get("name").asText());
		assertEquals("Waffle", robot.get("type").asText());
		assertArrayEquals(new double[] { 0.5, 0.5, 0, 0 }, doubles(robot.get("pose")));
		assertEquals(0.287, robot.get("drive").get("wheelSeparation").asDouble());
		assertEquals(360, robot.get("lidar").get("beams").asInt());
	}

	@Test
	void sdfHasOneModelPerObjectAndFixedBodiesHaveMassZero() throws Exception {
		generator.generate(TestCases.small(), out);
		JsonNode objects = json("world.json").get("objects");
		Element world = (Element) xml("world.sdf").getElementsByTagName("world").item(0);
		NodeList models = world.getElementsByTagName("model");

		assertEquals(objects.size(), models.getLength());
		for (int i = 0; i < models.getLength(); i++) {
			Element model = (Element) models.item(i);
			JsonNode object = objects.get(i);
			assertEquals(object.get("name").asText(), model.getAttribute("name"));
			boolean fixed = object.get("mass").asDouble() == 0;
			assertEquals(fixed ? 1 : 0, model.getElementsByTagName("static").getLength(), model.getAttribute("name"));
			assertEquals(object.get("mass").asDouble(), Double.parseDouble(text(model, "mass")));
			assertEquals(1, model.getElementsByTagName("inertia").getLength());
			if (fixed) {
				assertEquals("0.0", text(model, "ixx"));
			}
		}
		Element human = (Element) models.item(objects.size() - 1);
		assertEquals("h1", human.getAttribute("name"));
		assertEquals("0.25", text(human, "radius"));
		assertEquals("17.952083", text(human, "ixx"));
		Element table = (Element) models.item(objects.size() - 2);
		assertEquals("1.5 0.5 0.375 0 0 1.570796", text(table, "pose"));
		assertEquals("1.2 0.8 0.75", text(table, "size"));
	}

	private static String text(Element parent, String tag) {
		return parent.getElementsByTagName(tag).item(0).getTextContent().trim();
	}

	@Test
	void missionXmlHasStartAndGoalsInOrder() throws Exception {
		generator.generate(TestCases.small(), out);
		Element mission = xml("mission.xml").getDocumentElement();

		assertEquals("Deliver", mission.getAttribute("name"));
		assertEquals("SmallRoom", mission.getAttribute("testcase"));
		assertEquals("Lab", mission.getAttribute("environment"));
		assertEquals("tb3", mission.getAttribute("robot"));
		Element start = (Element) mission.getElementsByTagName("start").item(0);
		assertEquals("F_0_0", start.getAttribute("floor"));
		assertEquals("0.5", start.getAttribute("x"));
		NodeList goals = mission.getElementsByTagName("goal");
		assertEquals(2, goals.getLength());
		Element first = (Element) goals.item(0);
		assertEquals("0", first.getAttribute("index"));
		assertEquals("F_2_1", first.getAttribute("floor"));
		assertEquals("2.5", first.getAttribute("x"));
		assertEquals("1.5", first.getAttribute("y"));
		assertEquals("0.25", first.getAttribute("tolerance"));
		assertEquals("60.0", first.getAttribute("timeout"));
		Element second = (Element) goals.item(1);
		assertEquals("F_0_0", second.getAttribute("floor"));
		assertEquals("120.0", second.getAttribute("timeout"), "the mission's default");
	}

	@Test
	void animationListsTheHumansControlPoints() throws Exception {
		generator.generate(TestCases.small(), out);
		JsonNode animation = json("animation.json");

		assertEquals("rei-animation/1", animation.get("format").asText());
		assertEquals(1, animation.get("objects").size());
		JsonNode human = animation.get("objects").get(0);
		assertEquals("h1", human.get("name").asText());
		assertEquals("HUMAN", human.get("category").asText());
		assertTrue(human.get("loop").asBoolean());
		JsonNode points = human.get("points");
		assertEquals(3, points.size());
		assertEquals(15.5, points.get(2).get("t").asDouble());
		assertEquals(2.5, points.get(2).get("x").asDouble());
		assertEquals(0.5, points.get(2).get("y").asDouble());
		assertEquals("F_2_0", points.get(2).get("floor").asText());
		assertFalse(animation.has("people"), "no people, no member: cases without them keep their bytes");
		assertTrue(Files.readString(out.resolve("animation.json")).endsWith("}]}\n  ]\n}\n"));
	}

	/** docs/artifacts.md: people who see the robot are listed in "people", never among the objects on rails. */
	@Test
	void peopleOnARouteAreListedApartFromTheObjectsOnRails() throws Exception {
		generator.generate(TestCases.withPeople(), out);
		JsonNode animation = json("animation.json");

		assertEquals(List.of("h1"), names(animation.get("objects")));
		String text = Files.readString(out.resolve("animation.json"));
		String people = text.substring(text.indexOf("  \"people\""));
		assertEquals("""
				  "people": [
				    {"name": "ann", "behaviour": "avoids", "speed": 1.2, "start": 0.0, "loop": false,
				     "route": [{"floor": "F_2_1", "x": 2.5, "y": 1.5, "wait": 0.0}, {"floor": "F_1_1", "x": 1.5, "y": 1.5, "wait": 3.0}, {"floor": "F_2_0", "x": 2.5, "y": 0.5, "wait": 0.0}]},
				    {"name": "bob", "behaviour": "curious", "speed": 0.8, "start": 5.5, "loop": true,
				     "route": [{"floor": "F_1_1", "x": 1.5, "y": 1.5, "wait": 0.0}]}
				  ]
				}
				""", people);
		assertEquals(2, animation.get("people").size(), "valid JSON");
	}

	/** A person on a route is a human body as one on rails is, standing on its first stop. */
	@Test
	void peopleOnARouteAreHumanBodiesOnTheirFirstStop() throws Exception {
		generator.generate(TestCases.withPeople(), out);
		JsonNode objects = json("world.json").get("objects");

		JsonNode ann = named(objects, "ann");
		assertEquals("HUMAN", ann.get("category").asText());
		assertEquals("Human", ann.get("type").asText());
		assertEquals("F_2_1", ann.get("floor").asText());
		assertArrayEquals(new double[] { 2.5, 1.5, 0.85, 0.0 }, doubles(ann.get("pose")));
		assertEquals(named(objects, "h1").get("size"), ann.get("size"));
		assertEquals(named(objects, "h1").get("mass"), ann.get("mass"));
		assertEquals("F_1_1", named(objects, "bob").get("floor").asText());
		NodeList models = xml("world.sdf").getElementsByTagName("model");
		List<String> sdf = new ArrayList<>();
		for (int i = 0; i < models.getLength(); i++) {
			sdf.add(((Element) models.item(i)).getAttribute("name"));
		}
		assertEquals(names(objects), sdf);
		assertEquals(List.of("Floor", "Wall", "Table", "Human", "Waffle"), names(json("monitor.json").get("catalogue")));
	}

	@Test
	void aStopOffTheRoomIsAnError() {
		TestCase testCase = TestCases.withPeople();
		Floor elsewhere = ContextFactory.eINSTANCE.createFloor();
		elsewhere.setName("F_9_9");
		((org.rei.context.Human) testCase.getOwnedEnvironment().getOwnedObjects().get(2)).getOwnedRoute()
				.getOwnedStops().get(1).setFloor(elsewhere);

		GenerationException e = assertThrows(GenerationException.class, () -> generator.generate(testCase, out));

		assertTrue(e.getMessage().contains("a stop of ann's route"), e.getMessage());
	}

	private static List<String> names(JsonNode array) {
		List<String> names = new ArrayList<>();
		array.forEach(node -> names.add(node.get("name").asText()));
		return names;
	}

	@Test
	void monitorUsesDefaultThresholdsAndListsUsedTypes() throws Exception {
		generator.generate(TestCases.small(), out);
		JsonNode monitor = json("monitor.json");

		assertEquals("rei-monitor/1", monitor.get("format").asText());
		assertEquals("tb3", monitor.get("robot").asText());
		assertEquals(0.25, monitor.get("thresholds").get("close").asDouble());
		assertEquals(0.01, monitor.get("thresholds").get("collision").asDouble());
		assertEquals(1, monitor.get("requirements").get("maxHumanCollisions").asInt());
		assertEquals("rei.run.{run_id}.mission_info", monitor.get("topics").get("missionInfo").asText());
		List<String> types = new ArrayList<>();
		monitor.get("catalogue").forEach(t -> types.add(t.get("name").asText()));
		assertEquals(List.of("Floor", "Wall", "Table", "Human", "Waffle"), types);
		assertEquals(20.0, named(monitor.get("catalogue"), "Table").get("mass").asDouble());
	}

	@Test
	void monitorSpecOfTheTestCaseWins() throws Exception {
		TestCase testCase = TestCases.small();
		MonitorSpec spec = ContextFactory.eINSTANCE.createMonitorSpec();
		spec.setEpsClose(0.5);
		spec.setMaxHumanCollisions(3);
		testCase.setOwnedMonitor(spec);

		generator.generate(testCase, out);
		JsonNode monitor = json("monitor.json");

		assertEquals(0.5, monitor.get("thresholds").get("close").asDouble());
		assertEquals(3, monitor.get("requirements").get("maxHumanCollisions").asInt());
	}

	@Test
	void overrideTemplateReplacesOneFile(@TempDir Path templates) throws Exception {
		Files.writeString(templates.resolve("mission.xml.egl"), "<custom robot=\"[%=mission.robot%]\"/>\n");
		Files.writeString(templates.resolve("unrelated.txt"), "ignored");
		Path defaults = out.resolve("defaults");
		generator.generate(TestCases.small(), defaults);

		new ArtifactGenerator(new GeneratorOptions(templates)).generate(TestCases.small(), out);

		assertEquals("<custom robot=\"tb3\"/>\n", Files.readString(out.resolve("mission.xml")));
		assertEquals(Files.readString(defaults.resolve("world.json")), Files.readString(out.resolve("world.json")));
	}

	@Test
	void brokenOverrideFailsAtConstruction(@TempDir Path templates) throws Exception {
		Files.writeString(templates.resolve("world.json.egl"), "[% for (x in { %]");

		assertThrows(IllegalArgumentException.class, () -> new ArtifactGenerator(new GeneratorOptions(templates)));
	}

	@Test
	void failingTemplateLeavesTheGeneratorUsable(@TempDir Path templates) throws Exception {
		Files.writeString(templates.resolve("monitor.json.egl"),
				"[% if (testcase == \"Bad\") { var x = null; x.explode(); } %]ok [%=testcase%]\n");
		ArtifactGenerator custom = new ArtifactGenerator(new GeneratorOptions(templates));
		TestCase bad = TestCases.small();
		bad.setName("Bad");

		GenerationException e = assertThrows(GenerationException.class, () -> custom.generate(bad, out.resolve("bad")));
		assertTrue(e.getMessage().contains("monitor.json.egl"), e.getMessage());
		custom.generate(TestCases.small(), out);

		assertEquals("ok SmallRoom\n", Files.readString(out.resolve("monitor.json")));
	}

	@Test
	void layoutFailureCarriesTheProblems() {
		TestCase testCase = TestCases.small();
		Floor island = ContextFactory.eINSTANCE.createFloor();
		island.setName("island");
		testCase.getOwnedEnvironment().getOwnedBlocks().add(island);

		GenerationException e = assertThrows(GenerationException.class, () -> generator.generate(testCase, out));

		assertEquals(1, e.problems().size());
		LayoutProblem problem = e.problems().get(0);
		assertEquals(LayoutIssueCodes.DISCONNECTED, problem.code());
		assertEquals(island, problem.element());
		assertTrue(e.getMessage().contains("island"), e.getMessage());
		assertTrue(Files.notExists(out.resolve("world.json")), "nothing is written");
	}

	@Test
	void objectWithoutFloorIsAnError() {
		TestCase testCase = TestCases.small();
		testCase.getOwnedEnvironment().getOwnedObjects().get(0).setFloor(null);

		GenerationException e = assertThrows(GenerationException.class, () -> generator.generate(testCase, out));

		assertTrue(e.getMessage().contains("table1"), e.getMessage());
		assertTrue(e.problems().isEmpty());
	}

	@Test
	void sameInputGivesIdenticalBytes() throws Exception {
		Path first = out.resolve("a");
		Path second = out.resolve("b");
		generator.generate(TestCases.small(), first);
		new ArtifactGenerator(GeneratorOptions.defaults()).generate(TestCases.small(), second);
		generator.generate(TestCases.grid(2, 2), out.resolve("other")); // a run in between leaves nothing behind

		for (String artifact : ArtifactGenerator.ARTIFACTS) {
			assertArrayEquals(Files.readAllBytes(first.resolve(artifact)), Files.readAllBytes(second.resolve(artifact)),
					artifact);
		}
		generator.generate(TestCases.small(), second);
		assertArrayEquals(Files.readAllBytes(first.resolve("world.sdf")), Files.readAllBytes(second.resolve("world.sdf")));
		assertNotEquals(Files.readString(first.resolve("world.json")), Files.readString(out.resolve("other/world.json")));
	}

	/**
	 * A POLYGON type (an L written clockwise, off its origin): world.json carries its vertices about the object's
	 * pose, the bounding box's centre on the floor centre, counter-clockwise; size is the bounding box; world.sdf a
	 * polyline from the floor up; the table's line stays as a box's, with no footprint.
	 */
	@Test
	void polygonFurnitureCarriesItsFootprint() throws Exception {
		TestCase testCase = TestCases.small();
		org.rei.catalogue.ObjectType desk = org.rei.catalogue.CatalogueFactory.eINSTANCE.createObjectType();
		desk.setName("CornerDesk");
		desk.setCategory(org.rei.catalogue.ObjectCategory.STATIC);
		desk.setShape(org.rei.catalogue.Shape.POLYGON);
		desk.setSizeZ(0.75);
		double[][] clockwise = { { 2, 1 }, { 2, 2.4 }, { 2.6, 2.4 }, { 2.6, 1.6 }, { 3.6, 1.6 }, { 3.6, 1 } };
		for (double[] p : clockwise) {
			org.rei.catalogue.Vertex v = org.rei.catalogue.CatalogueFactory.eINSTANCE.createVertex();
			v.setX(p[0]);
			v.setY(p[1]);
			desk.getVertices().add(v);
		}
		org.rei.context.StaticObject table = (org.rei.context.StaticObject) testCase.getOwnedEnvironment()
				.getOwnedObjects().get(0);
		table.setType(desk);
		generator.generate(testCase, out);

		JsonNode placed = named(json("world.json").get("objects"), "table1");
		assertEquals("POLYGON", placed.get("shape").asText());
		assertArrayEquals(new double[] { 1.6, 1.4, 0.75 }, doubles(placed.get("size")), 1e-9);
		assertArrayEquals(new double[] { 1.5, 0.5, 0.375, 1.570796 }, doubles(placed.get("pose")), 1e-9);
		JsonNode footprint = placed.get("footprint");
		assertEquals("polygon", footprint.get("type").asText());
		double[][] expected = { { -0.8, -0.7 }, { 0.8, -0.7 }, { 0.8, -0.1 }, { -0.2, -0.1 }, { -0.2, 0.7 },
				{ -0.8, 0.7 } };
		assertEquals(expected.length, footprint.get("points").size());
		for (int i = 0; i < expected.length; i++) {
			assertArrayEquals(expected[i], doubles(footprint.get("points").get(i)), 1e-9, "vertex " + i);
		}
		JsonNode type = named(json("monitor.json").get("catalogue"), "CornerDesk");
		assertArrayEquals(new double[] { 1.6, 1.4, 0.75 }, doubles(type.get("size")), 1e-9);
		String sdf = Files.readString(out.resolve("world.sdf"));
		assertTrue(sdf.contains("<pose>0 0 -0.375 0 0 0</pose><geometry><polyline><point>-0.8 -0.7</point>"), sdf);
		assertTrue(sdf.contains("<height>0.75</height></polyline>"), sdf);
		assertFalse(named(json("world.json").get("objects"), "h1").has("footprint"));
	}
}
