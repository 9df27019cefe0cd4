/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.Value;
import org.msgpack.value.ValueType;
import org.msgpack.jackson.dataformat.MessagePackFactory;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** The payloads of docs/sut.md, decoded from and encoded to msgpack as jawampa does. */
class MessagesTest {

	static final ObjectMapper MSGPACK = new ObjectMapper(new MessagePackFactory());
	static final ObjectMapper JSON = new ObjectMapper();

	static final String HELLO = """
			{"protocol": 1, "run_id": "r1", "clock": "lockstep", "control_rate": 10.0, "deadline": 10,
			 "start": [0.5, 0.5, 0.0],
			 "robot": {"name": "tb3", "footprint": [0.281, 0.306], "max_linear": 0.26, "max_angular": 1.82,
			           "lidar": {"beams": 360, "range_min": 0.12, "range_max": 3.5, "rate": 10.0}},
			 "goals": 2, "map": null}""";

	static final String SCAN = """
			{"t": 0.1, "angle_min": -3.14159, "angle_max": 3.14159, "angle_increment": 1.5708, "scan_time": 0.1,
			 "range_min": 0.12, "range_max": 3.5, "ranges": [1.0, 2.0, 3.0, null]}""";

	/** A JSON text as the msgpack tree jawampa hands over (floats stay floats, integers integers). */
	static JsonNode msgpack(String json) throws Exception {
		return MSGPACK.readTree(MSGPACK.writeValueAsBytes(JSON.readTree(json)));
	}

	static String tick(long n, String scan) {
		return "{\"tick\": " + n + ", \"t\": " + n / 10.0
				+ ", \"odom\": {\"pose\": [0.5, 0.5, 0.1], \"twist\": [0.2, 0]}, \"scan\": " + scan + "}";
	}

	@Test
	void decodesHello() throws Exception {
		Session s = Messages.session(msgpack(HELLO));
		assertEquals("r1", s.runId());
		assertEquals(Session.Clock.LOCKSTEP, s.clock());
		assertEquals(10.0, s.deadline()); // an integer where a float is due
		assertEquals(new Pose(0.5, 0.5, 0.0), s.start());
		assertEquals(0.26, s.robot().maxLinear());
		assertEquals(360, s.robot().lidar().beams());
		assertEquals(0.0, s.robot().lidar().x(), "a simulation without the lidar's place: at the centre");
		assertEquals(2, s.goals());
		assertNull(s.map());
	}

	@Test
	void decodesWhereTheLidarSits() throws Exception {
		String placed = HELLO.replace("\"rate\": 10.0}", "\"rate\": 10.0, \"x\": 0.05, \"y\": -0.02, \"yaw\": 3}");
		Session s = Messages.session(msgpack(placed));
		assertEquals(new Session.Lidar(360, 0.12, 3.5, 10.0, 0.05, -0.02, 3.0), s.robot().lidar());
	}

	@Test
	void decodesTheMap() throws Exception {
		String hello = HELLO.replace("\"map\": null",
				"\"map\": {\"bounds\": [0, 0, 6, 4], \"obstacles\": [[2.5, 1.5, 0.0, 1.2, 0.8]]}");
		Session.StaticMap map = Messages.session(msgpack(hello)).map();
		assertEquals(6.0, map.xmax());
		assertEquals(List.of(new Session.Obstacle(2.5, 1.5, 0.0, 1.2, 0.8)), map.obstacles());
		assertNull(map.occupancy()); // a room of rectangles, not from an occupancy map
		assertNull(map.occupancyPath(Path.of("/case")));
		assertNull(map.occupancyPath(Map.of(SutClient.ENV_CASE_DIR, "/case")));
	}

	static String helloWithOccupancy(String value) {
		return HELLO.replace("\"map\": null", "\"map\": {\"bounds\": [0, 0, 10, 6], "
				+ "\"obstacles\": [[5.0, 0.075, 0.0, 10.0, 0.15]], \"occupancy\": " + value + "}");
	}

	@Test
	void namesTheOccupancyMapInTheCaseFolder(@TempDir Path caseDir) throws Exception {
		Files.writeString(caseDir.resolve("map.yaml"), "image: map.pgm\n");
		Session.StaticMap map = Messages.session(msgpack(helloWithOccupancy("\"map.yaml\""))).map();
		assertEquals("map.yaml", map.occupancy());
		assertEquals(List.of(new Session.Obstacle(5.0, 0.075, 0.0, 10.0, 0.15)), map.obstacles());
		Path resolved = map.occupancyPath(caseDir);
		assertEquals(caseDir.resolve("map.yaml"), resolved);
		assertEquals("image: map.pgm\n", Files.readString(resolved));
		assertEquals(resolved, map.occupancyPath(Map.of(SutClient.ENV_CASE_DIR, caseDir.toString())));
		// as the Python kit: without a case folder (REI_CASE_DIR unset or empty), the name as it is
		assertEquals(Path.of("map.yaml"), map.occupancyPath((Path) null));
		assertEquals(Path.of("map.yaml"), map.occupancyPath(Map.of()));
		assertEquals(Path.of("map.yaml"), map.occupancyPath(Map.of(SutClient.ENV_CASE_DIR, "")));
		assertEquals(map.occupancyPath(System.getenv()), map.occupancyPath());
		assertNull(Messages.session(msgpack(helloWithOccupancy("null"))).map().occupancy());
	}

	@Test
	void refusesAnOccupancyThatIsNotAString() throws Exception {
		for (String value : List.of("3", "[\"map.yaml\"]", "{\"yaml\": \"map.yaml\"}", "true")) {
			SutException e = assertThrows(SutException.class,
					() -> Messages.session(msgpack(helloWithOccupancy(value))), value);
			assertEquals(SutClient.EXIT_CONNECTION, e.exitCode());
			assertEquals("malformed hello's answer: map from the simulation: 'occupancy' is not a string",
					e.getMessage());
		}
	}

	@Test
	void refusesAnotherProtocolAndMalformedFields() throws Exception {
		SutException e = assertThrows(SutException.class,
				() -> Messages.session(msgpack(HELLO.replace("\"protocol\": 1", "\"protocol\": 2"))));
		assertEquals(SutClient.EXIT_CONNECTION, e.exitCode());
		e = assertThrows(SutException.class, () -> Messages.tick(msgpack("{\"tick\": 1, \"t\": 0.1}")));
		assertTrue(e.getMessage().contains("'odom' is missing"), e.getMessage());
		String shortTwist = tick(1, "null").replace("[0.2, 0]", "[0.2]");
		e = assertThrows(SutException.class, () -> Messages.tick(msgpack(shortTwist)));
		assertTrue(e.getMessage().contains("twist"), e.getMessage());
		String fractionalTick = tick(1, "null").replace("\"tick\": 1", "\"tick\": 1.5");
		assertThrows(SutException.class, () -> Messages.tick(msgpack(fractionalTick)));
	}

	@Test
	void decodesTicksWithAndWithoutScan() throws Exception {
		Messages.TickMessage t = Messages.tick(msgpack(tick(3, SCAN)));
		assertEquals(3, t.tick());
		assertEquals(new Pose(0.5, 0.5, 0.1), t.odom());
		assertEquals(new Twist(0.2, 0.0), t.twist());
		assertEquals(4, t.scan().ranges().length);
		assertEquals(Double.POSITIVE_INFINITY, t.scan().ranges()[3]);
		assertNull(Messages.tick(msgpack(tick(4, "null"))).scan());
		String noScanField = "{\"tick\": 4, \"t\": 0.4, \"odom\": {\"pose\": [0, 0, 0], \"twist\": [0, 0]}}";
		assertNull(Messages.tick(msgpack(noScanField)).scan());
	}

	@Test
	void readsInfinityFromMsgpack() throws Exception {
		byte[] bytes = MSGPACK.writeValueAsBytes(JSON.readTree(SCAN.replace("null", "1e400")));
		assertEquals(Double.POSITIVE_INFINITY, Messages.scan(MSGPACK.readTree(bytes)).ranges()[3]);
	}

	@Test
	void commandHasExactlyAnIntegerTickAndTwoFloats() throws Exception {
		byte[] bytes = MSGPACK.writeValueAsBytes(Messages.command(7, new Command(1, 0)));
		try (MessageUnpacker in = MessagePack.newDefaultUnpacker(bytes)) {
			var map = in.unpackValue().asMapValue().map();
			assertEquals(3, map.size());
			assertEquals(ValueType.INTEGER, value(map, "tick").getValueType());
			assertEquals(7, value(map, "tick").asIntegerValue().toLong());
			assertEquals(ValueType.FLOAT, value(map, "v").getValueType()); // 1.0, not 1
			assertEquals(ValueType.FLOAT, value(map, "w").getValueType());
		}
	}

	private static Value value(java.util.Map<Value, Value> map, String key) {
		return map.get(org.msgpack.value.ValueFactory.newString(key));
	}

	@Test
	void aHolonomicRobotsDriveTwistAndCommandCarryVy() throws Exception {
		Session.Robot holonomic = Messages.session(msgpack(HELLO.replace("\"max_angular\": 1.82,",
				"\"max_angular\": 1.82, \"drive\": \"holonomic\", \"max_lateral\": 0.26,"))).robot();
		assertTrue(holonomic.holonomic());
		assertEquals(0.26, holonomic.maxLateral());
		Session.Robot differential = Messages.session(msgpack(HELLO)).robot(); // a simulation before drives
		assertEquals("differential", differential.drive());
		assertEquals(0.0, differential.maxLateral());
		assertEquals(new Twist(0.2, 0.0, 0.15), Messages.tick(msgpack(tick(1, "null").replace("[0.2, 0]",
				"[0.2, 0, 0.15]"))).twist());
		assertEquals(new Command(0.26, 0, 0), new Command(1, 0, 0.5).clamp(differential));
		assertEquals(new Command(0.26, 0, -0.26), new Command(1, 0, -0.5).clamp(holonomic));
		assertEquals(0.15, Messages.command(3, new Command(0, 0, 0.15)).get("vy").asDouble());
		assertFalse(Messages.command(3, new Command(0.1, 0)).has("vy")); // a differential robot's, as always
	}

	@Test
	void readsTheRobotsOutline() throws Exception {
		assertNull(Messages.session(msgpack(HELLO)).robot().outline()); // a simulation before outlines
		Session.Outline circle = Messages.session(msgpack(HELLO.replace("\"max_angular\": 1.82,",
				"\"max_angular\": 1.82, \"outline\": {\"type\": \"circle\", \"x\": 0.05, \"y\": 0, \"radius\": 0.17},")))
				.robot().outline();
		assertTrue(circle.circle());
		assertEquals(0.17, circle.radius());
		assertEquals(0.05, circle.x());
		Session.Outline polygon = Messages.session(msgpack(HELLO.replace("\"max_angular\": 1.82,",
				"\"max_angular\": 1.82, \"outline\": {\"type\": \"polygon\", \"points\": [[-0.1, -0.1], [0.1, -0.1], [0, 0.1]]},")))
				.robot().outline();
		assertFalse(polygon.circle());
		assertEquals(3, polygon.points().size());
		assertEquals(-0.1, polygon.points().get(0)[1]);
		String bad = HELLO.replace("\"max_angular\": 1.82,", "\"max_angular\": 1.82, \"outline\": {\"type\": \"blob\"},");
		SutException e = assertThrows(SutException.class, () -> Messages.session(msgpack(bad)));
		assertTrue(e.getMessage().contains("unknown type 'blob'"), e.getMessage());
	}

	@Test
	void statusHasTextOnlyWhenGiven() {
		assertEquals("{\"goal_id\":1,\"status\":\"ACTIVE\"}", Messages.status(1, GoalStatus.ACTIVE, null).toString());
		assertEquals("{\"goal_id\":1,\"status\":\"ABORTED\",\"text\":\"stuck\"}",
				Messages.status(1, GoalStatus.ABORTED, "stuck").toString());
	}

	@Test
	void commandsAreFiniteAndCanBeClamped() {
		assertThrows(IllegalArgumentException.class, () -> new Command(Double.NaN, 0));
		assertThrows(IllegalArgumentException.class, () -> new Command(0, Double.POSITIVE_INFINITY));
		Session.Robot robot = new Session.Robot("r", 0.3, 0.3, 0.26, 1.82, new Session.Lidar(360, 0.1, 3.5, 10));
		assertEquals(new Command(0.26, -1.82), new Command(1, -5).clamp(robot));
	}

	@Test
	void geometryHelpers() {
		assertEquals(-Math.PI, Pose.normalize(Math.PI), 1e-12);
		assertEquals(0.5, Pose.normalize(0.5 + 4 * Math.PI), 1e-12);
		assertEquals(Math.PI / 2, new Pose(1, 1, 0).bearingTo(1, 2), 1e-12);
		assertEquals(-Math.PI / 2, new Pose(1, 1, Math.PI).bearingTo(1, 2), 1e-12);
		assertEquals(Math.sqrt(2), new Pose(0, 0, 0).distanceTo(new Pose(1, 1, 3)), 1e-12);
		Scan scan = new Scan(0, -Math.PI, Math.PI, Math.PI / 2, 0.1, 0.12, 3.5, new double[] { 1, 2, 3, 0.05 });
		// beams at -pi (behind), -pi/2 (right), 0 (ahead), pi/2 (left, below range_min: ignored)
		assertEquals(2.0, scan.minRange(-Math.PI / 2, 0.1));
		assertEquals(3.0, scan.minRange(-0.1, 0.1));
		assertEquals(Double.POSITIVE_INFINITY, scan.minRange(0.1, Math.PI - 0.1));
		assertFalse(scan.toString().contains("[D@"));
	}
}
