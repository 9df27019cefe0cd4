/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The command line is checked before anything starts: a bad one exits 2 with the reason and the usage. */
class MainOptionsTest {

	private record Outcome(int code, String out, String err) {
	}

	private static Outcome run(String... args) {
		ByteArrayOutputStream out = new ByteArrayOutputStream();
		ByteArrayOutputStream err = new ByteArrayOutputStream();
		int code = Main.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
				new PrintStream(err, true, StandardCharsets.UTF_8));
		return new Outcome(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
	}

	@ParameterizedTest(name = "{0} -> {1}")
	@CsvSource(delimiter = '|', value = {
			"'' | give exactly one of --router and --replay",
			"--router ws://127.0.0.1:1/ws --replay x --case c | give exactly one of --router and --replay",
			"--router ws://127.0.0.1:1/ws | live mode needs --run ID",
			"--router ws://127.0.0.1:1/ws --run a.b | run id must be 1-64 characters",
			"--router ws://127.0.0.1:1/ws --run 01234567890123456789012345678901234567890123456789012345678901234"
					+ " | run id must be 1-64 characters",
			"--replay out | replay needs --case DIR",
			"--router ws://127.0.0.1:1/ws --run | --run needs a value",
			"--router ws://127.0.0.1:1/ws --run r --verbose | unknown argument --verbose",
			"--router ws://127.0.0.1:1/ws --run r --timeout soon | --timeout needs a number of seconds > 0, got soon",
			"--router ws://127.0.0.1:1/ws --run r --timeout 0 | --timeout needs a number of seconds > 0, got 0",
			"--router ws://127.0.0.1:1/ws --run r --timeout -3 | --timeout needs a number of seconds > 0, got -3",
			"--router ws://127.0.0.1:1/ws --run r --timeout NaN | --timeout needs a number of seconds > 0, got NaN",
			"--router ws://127.0.0.1:1/ws --run r --until-end --linger -1 | --linger needs a number of seconds >= 0",
			"--router ws://127.0.0.1:1/ws --run r --linger 5 | --linger needs --until-end",
			"--router ws://127.0.0.1:1/ws --run r --mission m.msgpack | --mission applies to replay only",
			"--replay out --case c --record rec | --record applies to live mode (--router) only",
			"--replay out --case c --until-end | --until-end applies to live mode (--router) only",
			"--replay out --case c --timeout 5 | --timeout applies to live mode (--router) only",
	})
	void badCommandLinesExitTwoWithTheReasonAndTheUsage(String args, String reason) {
		Outcome o = run(args.isEmpty() ? new String[0] : args.split(" "));
		assertEquals(2, o.code(), o.err());
		assertTrue(o.err().startsWith("rei-monitor: "), o.err());
		assertTrue(o.err().contains(reason), o.err());
		assertTrue(o.err().contains("usage: java -jar rei-monitor.jar"), o.err());
		assertEquals("", o.out());
	}

	@Test
	void goodCommandLinesAreParsedAsGiven() {
		Main.Options live = Main.Options.parse(new String[] { "--router", "ws://127.0.0.1:9/ws", "--run", "run_1-A",
				"--until-end", "--linger", "2.5", "--timeout", "60", "--record", "rec", "--quiet", "--realm", "r2",
				"--snapshot-out", "s.xmi", "--signals-out", "sig.jsonl" });
		assertEquals("ws://127.0.0.1:9/ws", live.router);
		assertEquals("run_1-A", live.run);
		assertEquals("r2", live.realm);
		assertTrue(live.untilEnd && live.quiet);
		assertEquals(2.5, live.lingerSeconds, 0);
		assertEquals(60, live.timeoutSeconds, 0);
		assertEquals(Path.of("rec"), live.record);
		assertEquals(Path.of("s.xmi"), live.snapshotOut);
		assertEquals(Path.of("sig.jsonl"), live.signalsOut);
		Main.Options replay = Main.Options.parse(
				new String[] { "--replay", "out", "--case", "c", "--mission", "m.msgpack", "--queries", "q" });
		assertEquals(Path.of("out"), replay.replay);
		assertEquals("replay", replay.run);
		assertEquals(Path.of("m.msgpack"), replay.mission);
		assertEquals(Path.of("q"), replay.queries);
	}

	@Test
	void aMissingCaseFolderIsARuntimeFailureNotAUsageError(@org.junit.jupiter.api.io.TempDir Path tmp) {
		Outcome o = run("--replay", tmp.resolve("out").toString(), "--case", tmp.resolve("nope").toString());
		assertEquals(1, o.code(), o.err());
		assertTrue(o.err().contains("nope"), o.err());
		assertTrue(!o.err().contains("usage:"), o.err());
	}
}
