/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.dsl.edit.Texts;
import org.rei.dsl.validation.ReiIssueCodes;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The edit engine driven as the HTTP server drives it, in process: JSON lines through a pipe into
 * {@link EditServer#run()}, answers read line by line as they come. Each test ends by closing stdin; the server
 * must then return, and its stdout must have held nothing but one answer line per request.
 */
class EditServerTest {

	private static final ObjectMapper JSON = new ObjectMapper();

	@TempDir
	Path dir;

	private Path file;
	private String original;
	private PipedOutputStream stdin;
	private final Lines stdout = new Lines();
	private final ByteArrayOutputStream stderr = new ByteArrayOutputStream();
	private Thread server;
	private int requests;
	private final List<Throwable> failures = new ArrayList<>();

	@BeforeEach
	void start() throws IOException {
		file = dir.resolve("simple_navigation.rei");
		Files.copy(Texts.repository().resolve("examples/simple_navigation.rei"), file);
		original = Files.readString(file);
		PipedInputStream in = new PipedInputStream(1 << 20);
		stdin = new PipedOutputStream(in);
		EditServer engine = new EditServer(in, stdout, new PrintStream(stderr, true, StandardCharsets.UTF_8));
		server = new Thread(() -> {
			try {
				engine.run();
			} catch (Throwable e) {
				failures.add(e);
			}
		}, "edit-server");
		server.start();
	}

	@AfterEach
	void stdinClosesTheServer() throws Exception {
		stdin.close();
		server.join(10_000);
		assertFalse(server.isAlive(), "the server goes on after stdin closed");
		assertEquals(List.of(), failures);
		assertEquals(List.of(), stdout.unread(), "stdout holds lines that answer no request");
		assertEquals(requests, stdout.count(), "one answer line per request");
	}

	@Test
	void openStateApplyUndoRedoReset() throws Exception {
		JsonNode opened = ask("{\"id\": 1, \"command\": \"open\", \"path\": " + JSON.writeValueAsString(file.toString())
				+ "}");
		assertOk(opened, 1);
		assertEquals(original, opened.get("text").asText());
		assertEquals("SimpleNavigation", opened.at("/diagram/testCase").asText());
		assertEquals("F_2_1", opened.at("/diagram/objects/0/floor").asText());
		assertEquals(0, opened.get("issues").size());
		assertEquals(10, opened.get("palette").size());
		assertEquals(JSON.readTree("{\"name\": \"Table\", \"category\": \"object\", \"shape\": \"box\", \"sizeX\": 1.2, "
				+ "\"sizeY\": 0.8, \"colour\": \"#8B5A2B\"}"), opened.at("/palette/3"));
		assertFalse(opened.get("canUndo").asBoolean());
		assertFalse(opened.get("canRedo").asBoolean());

		JsonNode state = ask("{\"id\": 2, \"command\": \"state\"}");
		assertOk(state, 2);
		assertEquals(opened.get("diagram"), state.get("diagram"));

		JsonNode moved = ask("{\"id\": 3, \"command\": \"apply\", \"operations\": "
				+ "[{\"op\": \"moveObject\", \"name\": \"table1\", \"floor\": \"F_3_3\"}]}");
		assertOk(moved, 3);
		String movedText = original.replace("table1 : Table on F_2_1", "table1 : Table on F_3_3");
		assertEquals(movedText, moved.get("text").asText());
		assertEquals("F_3_3", moved.at("/diagram/objects/0/floor").asText());
		assertEquals(3.5, moved.at("/diagram/objects/0/x").asDouble());
		assertTrue(moved.get("canUndo").asBoolean());
		assertEquals(original, Files.readString(file), "the engine does not write the file");

		JsonNode undone = ask("{\"id\": 4, \"command\": \"undo\"}");
		assertOk(undone, 4);
		assertEquals(original, undone.get("text").asText());
		assertFalse(undone.get("canUndo").asBoolean());
		assertTrue(undone.get("canRedo").asBoolean());

		JsonNode redone = ask("{\"id\": 5, \"command\": \"redo\"}");
		assertEquals(movedText, redone.get("text").asText());
		assertTrue(redone.get("canUndo").asBoolean());
		assertFalse(redone.get("canRedo").asBoolean());

		String typed = original.replace("goto F_5_3", "goto F_5_2");
		JsonNode reset = ask("{\"id\": 6, \"command\": \"reset\", \"text\": " + JSON.writeValueAsString(typed) + "}");
		assertOk(reset, 6);
		assertEquals(typed, reset.get("text").asText());
		assertEquals("F_5_2", reset.at("/diagram/mission/goals/1/floor").asText());
		assertFalse(reset.get("canUndo").asBoolean());
		assertFalse(reset.get("canRedo").asBoolean());
		assertTrue(stderr.toString(StandardCharsets.UTF_8).contains("#3 apply ok"), stderr::toString);
	}

	@Test
	void everyOperationOfTheProtocol() throws Exception {
		open();
		String batch = "[{\"op\": \"addObject\", \"name\": \"chair1\", \"type\": \"Chair\", \"floor\": \"F_2_2\"},"
				+ "{\"op\": \"rotateObject\", \"name\": \"chair1\", \"yawDegrees\": 90},"
				+ "{\"op\": \"addHuman\", \"name\": \"visitor\", \"type\": null, \"points\": "
				+ "[{\"floor\": \"F_0_1\", \"seconds\": 0}, {\"floor\": \"F_5_1\", \"seconds\": 8}], \"loop\": true},"
				+ "{\"op\": \"addDynamic\", \"name\": \"cart1\", \"type\": \"Cart\", \"points\": "
				+ "[{\"floor\": \"F_1_1\", \"seconds\": 0}, {\"floor\": \"F_1_3\", \"seconds\": 2}], \"loop\": false},"
				+ "{\"op\": \"setTrajectory\", \"name\": \"walker\", \"points\": "
				+ "[{\"floor\": \"F_1_2\", \"seconds\": 0}, {\"floor\": \"F_3_1\", \"seconds\": 5.5}], \"loop\": false},"
				+ "{\"op\": \"addGoal\", \"floor\": \"F_4_3\", \"index\": 2, \"timeoutSeconds\": 30},"
				+ "{\"op\": \"moveGoal\", \"from\": 1, \"to\": 0}, {\"op\": \"removeGoal\", \"index\": 1}]";
		JsonNode result = ask("{\"id\": 7, \"command\": \"apply\", \"operations\": " + batch + "}");
		assertOk(result, 7);
		String text = result.get("text").asText();
		assertTrue(text.contains("    object chair1 : Chair on F_2_2 yaw 90\n"), text);
		assertTrue(text.contains("    human visitor trajectory [F_0_1 @ 0s, F_5_1 @ 8s] loop\n"), text);
		assertTrue(text.contains("    dynamic cart1 : Cart trajectory [F_1_1 @ 0s, F_1_3 @ 2s]\n"), text);
		assertTrue(text.contains("    human walker trajectory [F_1_2 @ 0s, F_3_1 @ 5.5s]\n"), text);
		assertTrue(text.contains("    goto F_5_3\n    goto F_4_3 within 30s\n  }"), text);
		assertEquals(0, result.get("issues").size(), () -> result.get("issues").toString());

		JsonNode deleted = ask("{\"id\": 8, \"command\": \"apply\", \"operations\": [{\"op\": \"deleteObject\", "
				+ "\"name\": \"chair1\"}]}");
		assertFalse(deleted.get("text").asText().contains("chair1"));
		// floors and walls: a grid room refuses them, a floor graph takes them
		JsonNode grid = ask("{\"id\": 9, \"command\": \"apply\", \"operations\": [{\"op\": \"addFloor\", "
				+ "\"name\": \"C\", \"neighbours\": {\"left\": \"F_5_0\"}}]}");
		assertRefused(grid, 9, "derives its floors and walls from its size 6 x 4");

		Path graph = dir.resolve("graph.rei");
		Files.copy(Path.of("src/test/resources/graph.rei"), graph);
		assertOk(ask("{\"id\": 10, \"command\": \"open\", \"path\": " + JSON.writeValueAsString(graph.toString())
				+ "}"), 10);
		JsonNode floors = ask("{\"id\": 11, \"command\": \"apply\", \"operations\": ["
				+ "{\"op\": \"addFloor\", \"name\": \"E\", \"neighbours\": {\"left\": \"D\"}},"
				+ "{\"op\": \"addWall\", \"name\": \"W_E_top\", \"floor\": \"E\", \"side\": \"top\"}]}");
		assertOk(floors, 11);
		assertTrue(floors.get("text").asText().contains("floor E left D top W_E_top"), floors.get("text")::asText);
		JsonNode removed = ask("{\"id\": 12, \"command\": \"apply\", \"operations\": ["
				+ "{\"op\": \"removeWall\", \"name\": \"W_E_top\"}, {\"op\": \"removeFloor\", \"name\": \"E\"}]}");
		assertEquals(Files.readString(graph), removed.get("text").asText());
	}

	/** A person on a route (the people example): setRoute as rei search sends it, and its fields checked. */
	@Test
	void setRouteOfAPersonOnARoute() throws Exception {
		file = dir.resolve("reactive_crossing.rei");
		Files.copy(Texts.repository().resolve("examples/people/reactive_crossing.rei"), file);
		open();
		JsonNode result = apply(2, "{\"op\": \"setRoute\", \"name\": \"bob\", \"stops\": [{\"floor\": \"F_5_0\", "
				+ "\"waitSeconds\": 0}, {\"floor\": \"F_6_3\", \"waitSeconds\": 1}], \"speed\": 1.2, \"start\": 4.5, "
				+ "\"loop\": false, \"behaviour\": \"scared\"}");
		assertOk(result, 2);
		assertTrue(result.get("text").asText().contains("\n    human bob route [F_5_0, F_6_3 wait 1s] start 4.5s scared\n"),
				result.get("text")::asText);
		assertEquals("scared", result.at("/diagram/movers/1/route/behaviour").asText());
		assertEquals(4.5, result.at("/diagram/movers/1/route/start").asDouble());

		assertRefused(apply(3, "{\"op\": \"setRoute\", \"name\": \"bob\", \"stops\": [{\"floor\": \"F_5_0\"}], "
				+ "\"speed\": 1, \"start\": 0, \"loop\": false, \"behaviour\": \"avoids\"}"), 3,
				"operation 0 (setRoute), stops[0]: missing field 'waitSeconds' (a number)");
		assertRefused(apply(4, "{\"op\": \"setRoute\", \"name\": \"bob\", \"stops\": [{\"floor\": \"F_5_0\", "
				+ "\"waitSeconds\": 0}], \"speed\": 1, \"start\": 0, \"loop\": false}"), 4,
				"operation 0 (setRoute): missing field 'behaviour' (a string)");
	}

	@Test
	void badRequestsAreAnsweredAndTheServerGoesOn() throws Exception {
		assertRefused(ask("{\"id\": 1, \"command\": \"state\"}"), 1, "no test case is open");
		assertRefused(ask("{\"id\": 2, \"command\": \"apply\", \"operations\": [{\"op\": \"moveObject\", "
				+ "\"name\": \"table1\", \"floor\": \"F_3_3\"}]}"), 2, "no test case is open");
		JsonNode malformed = ask("{\"id\": 3, \"command\": \"state\"");
		assertTrue(malformed.get("id").isNull());
		assertFalse(malformed.get("ok").asBoolean());
		assertTrue(malformed.get("error").asText().startsWith("malformed JSON: "), malformed::toString);
		assertEquals(Protocol.REFUSED, malformed.get("kind").asText(), malformed::toString);
		assertTrue(ask("[1, 2]").get("id").isNull());
		assertTrue(ask("{\"id\": 4} {\"id\": 5}").get("error").asText().startsWith("malformed JSON"));
		assertRefused(ask("{\"id\": 6}"), 6, "missing field 'command'");
		assertRefused(ask("{\"id\": 7, \"command\": \"save\"}"), 7, "unknown command 'save', expected one of open, "
				+ "state, apply, undo, redo, reset");
		assertRefused(ask("{\"id\": 8, \"command\": \"open\"}"), 8, "missing field 'path'");
		assertRefused(ask("{\"id\": 9, \"command\": \"open\", \"path\": \"" + dir + "/missing.rei\"}"), 9,
				"no such file");
		Path catalogue = dir.resolve("office.rei");
		Files.copy(Texts.repository().resolve("examples/catalogues/office.rei"), catalogue);
		assertRefused(ask("{\"id\": 10, \"command\": \"open\", \"path\": " + JSON.writeValueAsString(catalogue.toString())
				+ "}"), 10, "is not a test case");

		open();
		assertRefused(ask("{\"id\": 11, \"command\": \"undo\"}"), 11, "nothing to undo");
		assertRefused(ask("{\"id\": 12, \"command\": \"redo\"}"), 12, "nothing to redo");
		assertRefused(apply(13, "{\"op\": \"fly\", \"name\": \"table1\"}"), 13,
				"operation 0: unknown op 'fly', expected one of moveObject, rotateObject, addObject, deleteObject, "
						+ "addHuman, addDynamic, addFloor, removeFloor, addWall, removeWall, setTrajectory, setRoute, "
						+ "addCrowd, setCrowd, addGoal, removeGoal, moveGoal");
		assertRefused(apply(14, "{\"name\": \"table1\"}"), 14, "operation 0 has no 'op'");
		assertRefused(apply(15, "{\"op\": \"moveObject\", \"name\": \"table1\"}"), 15,
				"operation 0 (moveObject): missing field 'floor' (a string)");
		assertRefused(apply(15, "{\"op\": \"addDynamic\", \"name\": \"cart1\", \"type\": null, \"points\": "
				+ "[{\"floor\": \"F_1_1\", \"seconds\": 0}], \"loop\": false}"), 15,
				"operation 0 (addDynamic): missing field 'type' (a string)");
		assertRefused(apply(16, "{\"op\": \"removeGoal\", \"index\": 0.5}"), 16,
				"operation 0 (removeGoal): 'index' must be a whole number, got 0.5");
		assertRefused(apply(17, "{\"op\": \"addWall\", \"name\": \"W\", \"floor\": \"F_0_0\", \"side\": \"TOP\"}"),
				17, "'side' is 'TOP', expected top, right, bottom or left");
		assertRefused(apply(18, "{\"op\": \"setTrajectory\", \"name\": \"walker\", \"points\": [{\"floor\": "
				+ "\"F_1_2\"}], \"loop\": true}"), 18, "operation 0 (setTrajectory), points[0]: missing field "
						+ "'seconds' (a number)");
		assertRefused(ask("{\"id\": 19, \"command\": \"apply\", \"operations\": []}"), 19, "'operations' is empty");
		assertRefused(ask("{\"id\": 20, \"command\": \"reset\", \"text\": \"catalogue C { }\"}"), 20,
				"not a test case");

		JsonNode state = ask("{\"id\": \"last\", \"command\": \"state\"}");
		assertEquals("last", state.get("id").asText());
		assertTrue(state.get("ok").asBoolean());
		assertEquals(original, state.get("text").asText());
		assertFalse(state.get("canUndo").asBoolean());
	}

	@Test
	void aRefusedOrFailedApplyKeepsTheModel() throws Exception {
		open();
		assertOk(apply(2, "{\"op\": \"moveObject\", \"name\": \"table1\", \"floor\": \"F_3_3\"}"), 2);
		String moved = original.replace("on F_2_1", "on F_3_3");

		assertRefused(apply(3, "{\"op\": \"moveObject\", \"name\": \"table1\", \"floor\": \"F_9_9\"}"), 3,
				"Room 'Lab' has no floor or wall named 'F_9_9'");
		// the first operation is applied before the second is refused: the batch is undone as a whole
		assertRefused(apply(4, "{\"op\": \"moveObject\", \"name\": \"shelf1\", \"floor\": \"F_1_1\"}, "
				+ "{\"op\": \"deleteObject\", \"name\": \"tb3\"}"), 4, "a room has exactly one");
		// a batch with an undecodable operation is not applied at all
		assertRefused(apply(5, "{\"op\": \"moveObject\", \"name\": \"shelf1\", \"floor\": \"F_1_1\"}, "
				+ "{\"op\": \"moveGoal\", \"from\": 0}"), 5, "operation 1 (moveGoal): missing field 'to'");
		// a yaw the grammar cannot write: the read-back check fails inside the engine, which says so (internal), so
		// that a caller does not take its own failure for a fault of the edit
		JsonNode failed = apply(6, "{\"op\": \"rotateObject\", \"name\": \"table1\", \"yawDegrees\": 1e300}");
		assertFalse(failed.get("ok").asBoolean());
		assertEquals(Protocol.INTERNAL, failed.get("kind").asText(), failed::toString);
		assertTrue(failed.get("error").asText().contains("nothing was changed"), failed::toString);
		assertFalse(failed.get("error").asText().contains("\n"), failed::toString);

		JsonNode state = ask("{\"id\": 7, \"command\": \"state\"}");
		assertEquals(moved, state.get("text").asText());
		assertEquals("F_3_3", state.at("/diagram/objects/0/floor").asText());
		assertEquals("F_0_3", state.at("/diagram/objects/1/floor").asText());
		JsonNode undone = ask("{\"id\": 8, \"command\": \"undo\"}");
		assertEquals(original, undone.get("text").asText());
		assertFalse(undone.get("canUndo").asBoolean(), "a refused apply is no undo step");
	}

	@Test
	void anAnswerMadeWithoutJacksonIsAnInternalFailureOfTheSameRequest() throws Exception {
		// what the engine answers when even its failure handler fails (its jar rebuilt under it)
		NoClassDefFoundError gone = new NoClassDefFoundError("com/fasterxml/jackson/X \"\u00e9\"\nmore");
		JsonNode answer = JSON.readTree(EditServer.handMadeFailure("{\"id\": 42, \"command\": \"apply\"}", gone));
		assertEquals(List.of("id", "ok", "kind", "error"), fieldNames(answer));
		assertEquals(42, answer.get("id").asInt());
		assertFalse(answer.get("ok").asBoolean());
		assertEquals(Protocol.INTERNAL, answer.get("kind").asText());
		assertEquals("The edit engine failed (NoClassDefFoundError: com/fasterxml/jackson/X \"\u00e9\"); nothing was "
				+ "changed", answer.get("error").asText());
		String text = EditServer.handMadeFailure("{\"id\": \"a-1\", \"command\": \"state\"}", gone);
		assertTrue(text.chars().allMatch(c -> c < 128), text);
		assertEquals("a-1", JSON.readTree(text).get("id").asText());
		assertTrue(JSON.readTree(EditServer.handMadeFailure("[1, 2]", gone)).get("id").isNull());
	}

	@Test
	void aTakenFloorsIssueNamesBothObjects() throws Exception {
		open();
		JsonNode result = apply(2, "{\"op\": \"addObject\", \"name\": \"box1\", \"type\": \"Box\", \"floor\": "
				+ "\"F_2_1\"}");
		assertOk(result, 2);
		JsonNode issue = result.at("/issues/0");
		assertEquals(List.of("severity", "message", "line", "column", "offset", "length", "code", "element", "kind",
				"index", "related"), fieldNames(issue));
		assertEquals(ReiIssueCodes.FLOOR_OCCUPIED, issue.get("code").asText());
		assertEquals("box1", issue.get("element").asText());
		assertEquals(JSON.readTree("[\"table1\"]"), issue.get("related"));
		assertTrue(issue.get("index").isNull());
	}

	@Test
	void answersAreAsciiAndRequestsUtf8() throws Exception {
		open();
		String typed = "// Küche – ☕\n" + original;
		requests++;
		stdin.write(("{\"id\": 2, \"command\": \"reset\", \"text\": " + JSON.writeValueAsString(typed) + "}\n")
				.getBytes(StandardCharsets.UTF_8));
		stdin.flush();
		String line = stdout.next();
		assertTrue(line.chars().allMatch(c -> c < 128), line);
		assertTrue(line.contains("K\\u00FCche \\u2013 \\u2615"), line);
		assertEquals(typed, JSON.readTree(line).get("text").asText());
	}

	@Test
	void theAnswersCarryTheContractsFields() throws Exception {
		JsonNode opened = open();
		assertEquals(List.of("id", "ok", "text", "diagram", "issues", "palette", "canUndo", "canRedo"),
				fieldNames(opened));
		assertEquals(List.of("testCase", "room", "objects", "robot", "movers", "mission", "monitor", "crowds",
				"groups"), fieldNames(opened.get("diagram")));
		assertEquals(List.of("name", "kind", "floor", "yaw", "x", "y", "footprint"),
				fieldNames(opened.at("/diagram/robot")));
		assertEquals(List.of("name", "category", "shape", "sizeX", "sizeY", "colour"),
				fieldNames(opened.at("/palette/0")));
		assertEquals(List.of("id", "ok", "kind", "error"), fieldNames(ask("{\"id\": 2, \"command\": \"redo\"}")));
	}

	// -- the harness -------------------------------------------------------------------------------------------

	private JsonNode open() throws IOException, InterruptedException {
		JsonNode opened = ask("{\"id\": 1, \"command\": \"open\", \"path\": " + JSON.writeValueAsString(file.toString())
				+ "}");
		assertOk(opened, 1);
		return opened;
	}

	private JsonNode apply(int id, String operations) throws IOException, InterruptedException {
		return ask("{\"id\": " + id + ", \"command\": \"apply\", \"operations\": [" + operations + "]}");
	}

	/** Writes one request line and reads the answer line. */
	private JsonNode ask(String request) throws IOException, InterruptedException {
		requests++;
		stdin.write((request + "\n").getBytes(StandardCharsets.UTF_8));
		stdin.flush();
		String line = stdout.next();
		assertNotNull(line, () -> "no answer to " + request + "; stderr:\n" + stderr);
		return JSON.readTree(line);
	}

	private static void assertOk(JsonNode answer, int id) {
		assertTrue(answer.get("ok").asBoolean(), answer::toString);
		assertEquals(id, answer.get("id").asInt());
	}

	private static void assertRefused(JsonNode answer, int id, String message) {
		assertEquals(id, answer.get("id").asInt(), answer::toString);
		assertFalse(answer.get("ok").asBoolean(), answer::toString);
		assertEquals(Protocol.REFUSED, answer.get("kind").asText(), answer::toString);
		assertTrue(answer.get("error").asText().contains(message), answer.get("error")::asText);
	}

	private static List<String> fieldNames(JsonNode node) {
		List<String> names = new ArrayList<>();
		node.fieldNames().forEachRemaining(names::add);
		return names;
	}

	/** The server's stdout, cut into lines as they are written. */
	private static final class Lines extends OutputStream {
		private final ByteArrayOutputStream line = new ByteArrayOutputStream();
		private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
		private int count;

		@Override
		public synchronized void write(int b) {
			if (b == '\n') {
				lines.add(line.toString(StandardCharsets.UTF_8));
				count++;
				line.reset();
			} else {
				line.write(b);
			}
		}

		String next() throws InterruptedException {
			return lines.poll(60, TimeUnit.SECONDS);
		}

		synchronized int count() {
			return count;
		}

		synchronized List<String> unread() {
			List<String> rest = new ArrayList<>(lines);
			if (line.size() > 0) {
				rest.add(line.toString(StandardCharsets.UTF_8) + " (no line end)");
			}
			return rest;
		}
	}
}
