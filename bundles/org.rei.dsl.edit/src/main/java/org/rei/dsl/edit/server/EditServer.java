/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.server;

import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.rei.dsl.edit.EditRefusedException;
import org.rei.dsl.edit.RoomDocument;
import org.rei.dsl.edit.RoomEditSetup;
import org.rei.dsl.edit.ValidationIssue;

import com.fasterxml.jackson.annotation.JsonIgnore;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.json.JsonWriteFeature;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.NullNode;

/**
 * The room editor's edit engine (main class of rei-room-editor.jar): the HTTP server of {@code rei edit} starts it
 * as a child process and talks to it in JSON lines, as docs/room-editor.md ("HTTP server ⇄ edit engine") says.
 * <p>
 * One request per line on stdin (UTF-8), one answer line on stdout per request, in order (blank lines are skipped;
 * answers are ASCII, JSON's escapes standing for other characters); logs go
 * to stderr, and so does anything else that would print to {@code System.out} (Xtext's log4j configuration logs to
 * the console): stdout carries answers only. The engine exits 0 when stdin closes.
 * <p>
 * Every request is answered, whatever it holds: unreadable JSON, an unknown command or op, a missing field, a
 * command before {@code open} and a refused edit are answered
 * {@code {"id": N, "ok": false, "kind": "refused", "error": "..."}} (id null when the line is not a JSON object); a
 * failure inside the engine is answered the same with {@code "kind": "internal"}, so that a caller does not take it
 * for a fault of its request. Either way the document is as it was before the request.
 */
public final class EditServer {

	/**
	 * Records as their components, ValidationIssue without its convenience getter; answers in ASCII (other
	 * characters as \\u escapes), so that they read the same whatever encoding the reader assumes.
	 */
	private static final ObjectMapper MAPPER = JsonMapper.builder()
			.enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
			.enable(JsonWriteFeature.ESCAPE_NON_ASCII)
			.addMixIn(ValidationIssue.class, IssueMixIn.class)
			.build();

	/** A request's id as written at the start of its line: a number, a string without escapes, or null. */
	private static final Pattern REQUEST_ID = Pattern.compile(
			"^\\s*\\{\\s*\"id\"\\s*:\\s*(-?\\d+|\"[^\"\\\\]*\"|null)\\s*[,}]");

	private abstract static class IssueMixIn {
		@JsonIgnore
		abstract boolean isError();
	}

	private final BufferedReader requests;
	private final Writer answers;
	private final PrintStream log;
	private RoomDocument document;

	/**
	 * @param requests JSON lines, UTF-8
	 * @param answers receives one JSON line (UTF-8) per request, flushed after each
	 * @param log human-readable progress and failures
	 */
	public EditServer(InputStream requests, OutputStream answers, PrintStream log) {
		this.requests = new BufferedReader(new InputStreamReader(requests, StandardCharsets.UTF_8));
		this.answers = new BufferedWriter(new OutputStreamWriter(answers, StandardCharsets.UTF_8), 1 << 16);
		this.log = log;
	}

	public static void main(String[] args) {
		// the real stdout is kept for the answers; whatever else prints (log4j's console appender, EMF, a stray
		// printStackTrace) goes to stderr
		OutputStream stdout = new FileOutputStream(FileDescriptor.out);
		PrintStream stderr = System.err;
		System.setOut(stderr);
		EditServer server = new EditServer(System.in, stdout, stderr);
		int status = 0;
		try {
			server.warmUp();
			server.run();
		} catch (IOException e) {
			stderr.println("rei-room-editor: " + e);
			status = 1;
		}
		System.exit(status); // no thread of Xtext's or EMF's keeps the JVM once stdin is closed
	}

	/** Sets the language up while the first request is on its way: Xtext's injector takes most of a second. */
	void warmUp() {
		Thread thread = new Thread(RoomEditSetup::injector, "warm-up");
		thread.setDaemon(true);
		thread.start();
	}

	/** Answers requests until stdin closes. */
	public void run() throws IOException {
		log.println("rei-room-editor: ready (JSON lines on stdin: " + String.join(", ", Protocol.COMMANDS) + ")");
		for (String line = requests.readLine(); line != null; line = requests.readLine()) {
			if (line.isBlank()) {
				continue;
			}
			String answer;
			try {
				answer = answer(line);
			} catch (RuntimeException | LinkageError e) {
				// the failure handler failed too: the jar's own classes (Jackson's) can no longer be loaded, as when
				// the jar is rebuilt under the running engine; still an answer, an internal failure
				log.println("rei-room-editor: answering failed: " + e);
				answer = handMadeFailure(line, e);
			}
			answers.write(answer);
			answers.write('\n');
			answers.flush();
		}
		log.println("rei-room-editor: stdin closed, exiting");
	}

	/**
	 * The answer line to one request line; never throws but for what only kills the JVM anyway, or a failure of
	 * the failure handler itself ({@link #handMadeFailure}).
	 */
	String answer(String line) {
		long start = System.nanoTime();
		JsonNode request;
		try {
			request = MAPPER.readTree(line);
		} catch (JsonProcessingException e) {
			return error(NullNode.instance, "malformed JSON: " + e.getOriginalMessage() + " (one JSON object per "
					+ "line expected)", "?", start, Protocol.REFUSED);
		}
		if (request == null || !request.isObject()) {
			return error(NullNode.instance, "a request is a JSON object {\"id\": N, \"command\": C, ...}, got "
					+ OperationDecoder.describe(request == null ? NullNode.instance : request), "?", start,
					Protocol.REFUSED);
		}
		JsonNode id = request.hasNonNull("id") ? request.get("id") : NullNode.instance;
		String command = request.hasNonNull("command") ? request.get("command").asText() : "?";
		try {
			Map<String, Object> state = handle(request);
			Map<String, Object> answer = new LinkedHashMap<>();
			answer.put("id", id);
			answer.put("ok", true);
			answer.putAll(state);
			String json = MAPPER.writeValueAsString(answer);
			log.printf("rei-room-editor: #%s %s ok, %d ms, %,d characters%n", id, command, millis(start),
					json.length());
			return json;
		} catch (RequestException | EditRefusedException e) {
			return error(id, e.getMessage(), command, start, Protocol.REFUSED);
		} catch (Exception | StackOverflowError | LinkageError | AssertionError e) {
			// a failure of the engine: the document re-read its text (RoomDocument.apply), the server goes on
			log.println("rei-room-editor: #" + id + " " + command + " failed:");
			e.printStackTrace(log);
			return error(id, failure(e), command, start, Protocol.INTERNAL);
		}
	}

	private Map<String, Object> handle(JsonNode request) throws RequestException, IOException {
		JsonNode command = request.get("command");
		if (command == null || command.isNull()) {
			throw new RequestException("missing field 'command' (one of " + String.join(", ", Protocol.COMMANDS) + ")");
		}
		if (!command.isTextual()) {
			throw new RequestException("'command' must be a string (one of " + String.join(", ", Protocol.COMMANDS)
					+ "), got " + OperationDecoder.describe(command));
		}
		switch (command.asText()) {
		case "open":
			open(text(request, "path", "the test case's file"));
			return state();
		case "state":
			open();
			return state();
		case "apply":
			RoomDocument edited = open();
			edited.apply(OperationDecoder.decodeAll(request.get("operations")));
			return state();
		case "undo":
			if (!open().canUndo()) {
				throw new RequestException("nothing to undo");
			}
			document.undo();
			return state();
		case "redo":
			if (!open().canRedo()) {
				throw new RequestException("nothing to redo");
			}
			document.redo();
			return state();
		case "reset":
			String text = text(request, "text", "the file's new text");
			try {
				open().reset(text);
			} catch (IllegalArgumentException e) {
				throw new RequestException(e.getMessage());
			}
			return state();
		default:
			throw new RequestException("unknown command '" + command.asText() + "', expected one of "
					+ String.join(", ", Protocol.COMMANDS));
		}
	}

	/** Opens a file, replacing the open document; a file that cannot be opened leaves the open one as it was. */
	private void open(String path) throws RequestException, IOException {
		Path file;
		try {
			file = Path.of(path);
		} catch (InvalidPathException e) {
			throw new RequestException("cannot open '" + path + "': " + e.getMessage());
		}
		try {
			document = RoomDocument.open(file);
			log.println("rei-room-editor: opened " + document.uri().toFileString());
		} catch (NoSuchFileException e) {
			throw new RequestException("cannot open '" + path + "': no such file");
		} catch (IllegalArgumentException e) {
			throw new RequestException("cannot open '" + path + "': " + e.getMessage());
		} catch (IOException e) {
			throw new RequestException("cannot open '" + path + "': " + e);
		}
	}

	private RoomDocument open() throws RequestException {
		if (document == null) {
			throw new RequestException("no test case is open: send {\"id\": N, \"command\": \"open\", \"path\": "
					+ "\"CASE.rei\"} first");
		}
		return document;
	}

	private Map<String, Object> state() {
		Map<String, Object> state = new LinkedHashMap<>();
		state.put("text", document.text());
		state.put("diagram", document.diagram());
		state.put("issues", document.issues());
		state.put("palette", document.palette());
		state.put("canUndo", document.canUndo());
		state.put("canRedo", document.canRedo());
		return state;
	}

	private static String text(JsonNode request, String field, String what) throws RequestException {
		JsonNode value = request.get(field);
		if (value == null || value.isNull()) {
			throw new RequestException("missing field '" + field + "' (" + what + ")");
		}
		if (!value.isTextual()) {
			throw new RequestException("'" + field + "' must be a string (" + what + "), got "
					+ OperationDecoder.describe(value));
		}
		return value.asText();
	}

	/** An {@code ok: false} answer; {@code kind}: {@link Protocol#REFUSED} or {@link Protocol#INTERNAL}. */
	private String error(JsonNode id, String message, String command, long start, String kind) {
		log.printf("rei-room-editor: #%s %s %s, %d ms: %s%n", id, command,
				Protocol.REFUSED.equals(kind) ? "refused" : "failed", millis(start), firstLine(message));
		Map<String, Object> answer = new LinkedHashMap<>();
		answer.put("id", id);
		answer.put("ok", false);
		answer.put("kind", kind);
		answer.put("error", message);
		try {
			return MAPPER.writeValueAsString(answer);
		} catch (JsonProcessingException e) {
			throw new IllegalStateException(e); // a node, a boolean and a string always write
		}
	}

	/**
	 * The answer to {@code line} when the engine failed so that even Jackson cannot be loaded: written with the
	 * JDK's classes only, its {@code id} taken from the line as written (the callers put it first; null when the
	 * line has none that reads as a number, a simple string or null).
	 */
	static String handMadeFailure(String line, Throwable e) {
		Matcher id = REQUEST_ID.matcher(line);
		return "{\"id\":" + (id.find() ? id.group(1) : "null") + ",\"ok\":false,\"kind\":\"" + Protocol.INTERNAL
				+ "\",\"error\":\"" + asciiJson(failure(e)) + "\"}";
	}

	/** {@code text} as the inside of a JSON string, in ASCII. */
	private static String asciiJson(String text) {
		StringBuilder out = new StringBuilder(text.length() + 16);
		for (char c : text.toCharArray()) {
			if (c == '"' || c == '\\') {
				out.append('\\').append(c);
			} else if (c < 0x20 || c > 0x7e) {
				out.append(String.format("\\u%04x", (int) c));
			} else {
				out.append(c);
			}
		}
		return out.toString();
	}

	/** An engine failure for the user: what failed, without the text a read-back failure appends. */
	private static String failure(Throwable e) {
		if (e.getMessage() != null && firstLine(e.getMessage()).contains("nothing was changed")) {
			return firstLine(e.getMessage()); // the read-back check's own words
		}
		String message = e.getMessage() == null ? e.getClass().getSimpleName()
				: e.getClass().getSimpleName() + ": " + firstLine(e.getMessage());
		return "The edit engine failed (" + message + "); nothing was changed";
	}

	private static String firstLine(String text) {
		int end = text.indexOf('\n');
		return end < 0 ? text : text.substring(0, end);
	}

	private static long millis(long start) {
		return (System.nanoTime() - start) / 1_000_000;
	}
}
