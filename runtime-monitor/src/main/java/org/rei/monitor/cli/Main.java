/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.cli;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rei.monitor.config.CaseReader;
import org.rei.monitor.engine.DrlSources;
import org.rei.monitor.model.Snapshots;
import org.rei.monitor.pipeline.Monitor;
import org.rei.monitor.replay.Recording;
import org.rei.monitor.replay.Replayer;
import org.rei.monitor.signals.SignalPublisher;
import org.rei.monitor.wamp.LiveMonitor;

/**
 * {@code java -jar rei-monitor.jar}: live ({@code --router URL --run ID}) or replay ({@code --replay FILE|DIR}).
 * Exit codes: 0 done, 1 runtime failure, 2 bad command line.
 */
public final class Main {

	static final String USAGE = """
			usage: java -jar rei-monitor.jar --router ws://HOST:PORT/ws --run ID [options]   (live)
			       java -jar rei-monitor.jar --replay STATE.msgpack|RUN_DIR --case DIR [options]   (replay)
			options:
			  --case DIR           world.json + monitor.json (live: default is the run's config RPC)
			  --mission FILE       replay: the mission stream (default: mission.msgpack beside the state stream)
			  --realm NAME         WAMP realm (default rei)
			  --queries DIR        .drl queries (default: the copies of queries/ in the jar)
			  --rules DIR          .drl transition rules (default: the copies of cep/drl/ in the jar)
			  --snapshot-out FILE  write the runtime model as XMI on exit (live default: runtime-<run>.xmi)
			  --record DIR         live: record the received streams (state.msgpack, mission.msgpack)
			  --until-end          live: stop after the mission's END event
			  --timeout SECONDS    live: stop after this long (default: run until interrupted)
			  --quiet              do not print signals
			""";

	private Main() {
	}

	public static void main(String[] args) {
		System.exit(run(args, System.out, System.err));
	}

	public static int run(String[] args, PrintStream out, PrintStream err) {
		Options o;
		try {
			o = Options.parse(args);
		} catch (IllegalArgumentException e) {
			err.println("rei-monitor: " + e.getMessage());
			err.print(USAGE);
			return 2;
		}
		try {
			return o.replay != null ? replay(o, out, err) : live(o, out, err);
		} catch (Exception e) {
			err.println("rei-monitor: " + e);
			return 1;
		}
	}

	static List<DrlSources.Source> rules(Options o) throws java.io.IOException {
		List<DrlSources.Source> rules = new ArrayList<>(
				o.queries != null ? DrlSources.folder(o.queries) : DrlSources.packaged(DrlSources.QUERIES));
		rules.addAll(o.rules != null ? DrlSources.folder(o.rules) : DrlSources.packaged(DrlSources.RULES));
		return rules;
	}

	private static int replay(Options o, PrintStream out, PrintStream err) throws Exception {
		Path state = o.replay;
		Path mission = o.mission;
		if (Files.isDirectory(state)) {
			Path streams = Files.isDirectory(state.resolve("streams")) ? state.resolve("streams") : state;
			state = streams.resolve("state.msgpack");
			if (mission == null) {
				mission = streams.resolve("mission.msgpack");
			}
		} else if (mission == null) {
			mission = state.resolveSibling("mission.msgpack");
		}
		CaseReader.Case c = CaseReader.readFolder(o.caseDir);
		SignalPublisher signals = new SignalPublisher();
		if (!o.quiet) {
			signals.addListener(s -> out.println(s.line()));
		}
		try (Monitor m = new Monitor(o.run, c.world(), c.monitor(), rules(o), signals, err::println, null)) {
			Recording missions = Files.exists(mission) ? Recording.read(mission) : null;
			long start = System.nanoTime();
			long[] latency = Replayer.replay(m, Recording.read(state), missions);
			double seconds = (System.nanoTime() - start) / 1e9;
			err.printf("replayed %d state and %d mission messages in %.3f s (%.0f states/s), %d signals, problems %s%n",
					m.statesProcessed(), m.missionsProcessed(), seconds, latency.length / seconds, signals.count(),
					m.guard().problems());
			if (o.snapshotOut != null) {
				Snapshots.save(m.model().resource(), o.snapshotOut);
			}
		}
		return 0;
	}

	private static int live(Options o, PrintStream out, PrintStream err) throws Exception {
		CaseReader.Case given = o.caseDir != null ? CaseReader.readFolder(o.caseDir) : null;
		List<DrlSources.Source> rules = rules(o);
		Path snapshotOut = o.snapshotOut != null ? o.snapshotOut : Path.of("runtime-" + o.run + ".xmi");
		try (LiveMonitor live = new LiveMonitor(o.router, o.realm, err::println)) {
			live.start(o.run, given,
					c -> new Monitor(o.run, c.world(), c.monitor(), rules, new SignalPublisher(), err::println, null),
					o.record, s -> {
						if (!o.quiet) {
							out.println(s.line());
							out.flush();
						}
					}, 30_000);
			Thread hook = new Thread(() -> { // interrupted (Ctrl-C, SIGTERM): still leave the model behind
				try {
					live.onPipeline(() -> save(live.monitor(), snapshotOut, err));
				} catch (Exception e) {
					err.println("rei-monitor: no snapshot on exit: " + e);
				}
			});
			Runtime.getRuntime().addShutdownHook(hook);
			long timeout = o.timeoutSeconds > 0 ? (long) (o.timeoutSeconds * 1000) : Long.MAX_VALUE;
			if (o.untilEnd) {
				live.awaitEnd(timeout);
			} else {
				Thread.sleep(timeout);
			}
			live.onPipeline(() -> {
				Monitor m = live.monitor();
				err.printf("processed %d state and %d mission messages, %d signals, problems %s%n", m.statesProcessed(),
						m.missionsProcessed(), m.signals().count(), m.guard().problems());
				save(m, snapshotOut, err);
			});
			Runtime.getRuntime().removeShutdownHook(hook);
		}
		return 0;
	}

	private static void save(Monitor m, Path file, PrintStream err) {
		try {
			Snapshots.save(m.model().resource(), file);
		} catch (Exception e) {
			err.println("rei-monitor: snapshot not written: " + e);
		}
	}

	/** The command line, checked at the door. */
	static final class Options {
		String router;
		String run = "replay";
		String realm = "rei";
		Path replay;
		Path mission;
		Path caseDir;
		Path queries;
		Path rules;
		Path snapshotOut;
		Path record;
		boolean untilEnd;
		boolean quiet;
		double timeoutSeconds;

		static Options parse(String[] args) {
			Options o = new Options();
			boolean runGiven = false;
			for (int i = 0; i < args.length; i++) {
				String a = args[i];
				switch (a) {
				case "--until-end" -> o.untilEnd = true;
				case "--quiet" -> o.quiet = true;
				case "--router", "--run", "--realm", "--replay", "--mission", "--case", "--queries", "--rules",
						"--snapshot-out", "--record", "--timeout" -> {
					if (i + 1 >= args.length) {
						throw new IllegalArgumentException(a + " needs a value");
					}
					String v = args[++i];
					switch (a) {
					case "--router" -> o.router = v;
					case "--run" -> {
						o.run = v;
						runGiven = true;
					}
					case "--realm" -> o.realm = v;
					case "--replay" -> o.replay = Path.of(v);
					case "--mission" -> o.mission = Path.of(v);
					case "--case" -> o.caseDir = Path.of(v);
					case "--queries" -> o.queries = Path.of(v);
					case "--rules" -> o.rules = Path.of(v);
					case "--snapshot-out" -> o.snapshotOut = Path.of(v);
					case "--record" -> o.record = Path.of(v);
					default -> o.timeoutSeconds = Double.parseDouble(v);
					}
				}
				default -> throw new IllegalArgumentException("unknown argument " + a);
				}
			}
			if ((o.router == null) == (o.replay == null)) {
				throw new IllegalArgumentException("give exactly one of --router and --replay");
			}
			if (o.router != null && !runGiven) {
				throw new IllegalArgumentException("live mode needs --run ID");
			}
			if (!o.run.matches("[A-Za-z0-9_-]{1,64}")) {
				throw new IllegalArgumentException("run id must be 1-64 characters of [A-Za-z0-9_-]: " + o.run);
			}
			if (o.replay != null && o.caseDir == null) {
				throw new IllegalArgumentException("replay needs --case DIR (world.json, monitor.json)");
			}
			return o;
		}
	}
}
