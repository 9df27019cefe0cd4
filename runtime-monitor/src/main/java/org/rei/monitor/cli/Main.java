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
import java.util.Map;

import org.rei.monitor.config.CaseReader;
import org.rei.monitor.config.MonitorSpec;
import org.rei.monitor.engine.DrlSources;
import org.rei.monitor.engine.PatternRules;
import org.rei.monitor.engine.SessionFactory;
import org.rei.monitor.model.Snapshots;
import org.rei.monitor.pipeline.Monitor;
import org.rei.monitor.replay.Recording;
import org.rei.monitor.replay.Replayer;
import org.rei.monitor.signals.SignalFile;
import org.rei.monitor.signals.SignalPublisher;
import org.rei.monitor.signals.UtilitiesFile;
import org.rei.monitor.wamp.LiveMonitor;
import org.rei.vepl.compiler.CompiledRules;
import org.rei.vepl.compiler.VeplLoader;
import org.rei.wamp.auth.RouterCredentials;
import org.rei.warmjvm.CommandServer;

/**
 * {@code java -jar rei-monitor.jar}: live ({@code --router URL --run ID}) or replay ({@code --replay FILE|DIR}), or
 * {@code --compile-only} to check a patterns folder before a run. Exit codes: 0 done, 1 runtime failure (also
 * patterns that do not validate), 2 bad command line.
 */
public final class Main {

	static final String USAGE = """
			usage: java -jar rei-monitor.jar --router ws://HOST:PORT/ws --run ID [options]   (live)
			       java -jar rei-monitor.jar --replay STATE.msgpack|RUN_DIR --case DIR [options]   (replay)
			       java -jar rei-monitor.jar --compile-only [--patterns DIR] [options]   (check the rules, exit)
			       java -jar rei-monitor.jar --serve SOCKET   (run many of the above in this JVM: org.rei.warmjvm)
			options:
			  --case DIR           world.json + monitor.json (live: default is the run's config RPC)
			  --mission FILE       replay: the mission stream (default: mission.msgpack beside the state stream)
			  --realm NAME         WAMP realm (default rei)
			  --auth-file FILE     live: the monitor role's credentials (0600 JSON written by the router;
			                       required by REI's authenticating router, docs/security.md)
			  --queries DIR        the user's .drl queries, beside the packaged ones (queries/): over the runtime
			                       model and the monitor's facts; --patterns may name them
			  --patterns DIR       .vepl patterns compiled at start, added to the default patterns (cep/patterns/)
			  --no-default-patterns  only the patterns of --patterns DIR
			  --rules DIR          hand-written .drl transition rules instead of any VEPL patterns
			  --utilities-out FILE write what the patterns in use declare of their signals, as JSON {"SIG_X":
			                       {"utility": -2.0, "transition": {"source": "GEOM", "from": "FAR", "to": "CLOSE"}}},
			                       once the rules are compiled, before any message ({} with --rules)
			  --compile-only       compile the queries and rules (and write --utilities-out), then exit
			  --snapshot-out FILE  write the runtime model as XMI on exit (live default: runtime-<run>.xmi)
			  --record DIR         live: record the received streams (state.msgpack, mission.msgpack)
			  --signals-out FILE   write every signal as a JSON line (exact numbers, for comparisons)
			  --until-end          live: stop after the mission's END event
			  --linger SECONDS     live, with --until-end: keep serving the snapshot RPC this long after END
			  --timeout SECONDS    live: stop after this long (default: run until interrupted)
			  --quiet              do not print signals
			""";

	private Main() {
	}

	public static void main(String[] args) {
		if (args.length == 2 && args[0].equals("--serve")) { // a warm JVM for many runs (org.rei.warmjvm)
			System.exit(CommandServer.serveUntilStdinCloses(Main::run, args[1], System.err));
		}
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
			return o.compileOnly ? compileOnly(o, err) : o.replay != null ? replay(o, out, err) : live(o, out, err);
		} catch (VeplLoader.VeplException e) { // the message lists file:line:column of every error
			err.println("rei-monitor: " + e.getMessage());
			return 1;
		} catch (IllegalArgumentException e) { // rule files that do not build: file:line of each error
			err.println("rei-monitor: " + e.getMessage());
			return 1;
		} catch (Exception e) {
			err.println("rei-monitor: " + e);
			return 1;
		}
	}

	/** The session's DRL (queries, then transition rules) and the utilities the patterns declare. */
	record Rules(List<DrlSources.Source> drl, Map<String, Double> utilities,
			Map<String, CompiledRules.Transition> transitions) {
	}

	/** Compiles the rules and writes {@code --utilities-out} at once, before any message is processed. */
	static Rules rules(Options o) throws Exception {
		List<DrlSources.Source> queries = new ArrayList<>(DrlSources.packaged(DrlSources.QUERIES));
		if (o.queries != null) {
			queries.addAll(DrlSources.folder(o.queries));
		}
		List<DrlSources.Source> drl = new ArrayList<>(queries);
		Map<String, Double> utilities = Map.of(); // hand-written DRL declares none
		Map<String, CompiledRules.Transition> transitions = Map.of();
		if (o.rules != null) {
			drl.addAll(DrlSources.folder(o.rules));
		} else {
			// VEPL patterns are compiled here, at start: a user's folder needs no rebuild of the monitor
			PatternRules.Compiled patterns = PatternRules
					.compileWithUtilities(PatternRules.select(!o.noDefaultPatterns, o.patterns), queries);
			drl.addAll(patterns.drl());
			utilities = patterns.utilities();
			transitions = patterns.transitions();
		}
		if (o.utilitiesOut != null) {
			UtilitiesFile.write(o.utilitiesOut, utilities, transitions);
		}
		return new Rules(drl, utilities, transitions);
	}

	private static int compileOnly(Options o, PrintStream err) throws Exception {
		Rules r = rules(o);
		SessionFactory.build(r.drl()).dispose(); // the queries and the rules must also build together
		err.printf("compiled %d rule files, %d signals declared%n", r.drl().size(), r.utilities().size());
		return 0;
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
		List<DrlSources.Source> rules = rules(o).drl();
		SignalPublisher signals = new SignalPublisher();
		if (!o.quiet) {
			signals.addListener(s -> out.println(s.line()));
		}
		try (SignalFile file = o.signalsOut != null ? new SignalFile(o.signalsOut) : null;
				Monitor m = new Monitor(o.run, c.world(), c.monitor(), rules, signals, err::println, null)) {
			if (file != null) {
				signals.addListener(file);
			}
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
		List<DrlSources.Source> rules = rules(o).drl();
		Path snapshotOut = o.snapshotOut != null ? o.snapshotOut : Path.of("runtime-" + o.run + ".xmi");
		try (SignalFile file = o.signalsOut != null ? new SignalFile(o.signalsOut) : null;
				LiveMonitor live = new LiveMonitor(o.router, o.realm,
						o.authFile != null ? RouterCredentials.read(o.authFile) : null, err::println)) {
			live.start(o.run, given,
					c -> new Monitor(o.run, c.world(), c.monitor(), rules, new SignalPublisher(), err::println, null),
					o.record, s -> {
						if (file != null) {
							file.accept(s);
						}
						if (!o.quiet) {
							out.println(s.line());
							out.flush();
						}
					}, o.timeoutSeconds > 0 ? (long) (o.timeoutSeconds * 1000) : 30_000);
			Thread hook = new Thread(() -> { // interrupted (Ctrl-C, SIGTERM): still leave the model behind
				try {
					live.onPipeline(() -> save(live.monitor(), snapshotOut, err));
				} catch (Exception e) {
					err.println("rei-monitor: no snapshot on exit: " + e);
				}
			});
			Runtime.getRuntime().addShutdownHook(hook);
			try {
				long timeout = o.timeoutSeconds > 0 ? (long) (o.timeoutSeconds * 1000) : Long.MAX_VALUE;
				if (o.untilEnd) {
					if (!live.awaitEnd(timeout)) {
						err.println("rei-monitor: no END event within " + o.timeoutSeconds + " s");
					} else if (o.lingerSeconds > 0) {
						Thread.sleep((long) (o.lingerSeconds * 1000)); // the final model stays available over WAMP
					}
				} else {
					Thread.sleep(timeout);
				}
			} catch (InterruptedException e) { // cancelled in a warm JVM (org.rei.warmjvm): still leave the model
				hook.run();
				throw e;
			} finally {
				Runtime.getRuntime().removeShutdownHook(hook); // a warm JVM serves many runs: no hook left behind
			}
			live.onPipeline(() -> {
				Monitor m = live.monitor();
				err.printf("processed %d state and %d mission messages, %d signals, problems %s%n", m.statesProcessed(),
						m.missionsProcessed(), m.signals().count(), m.guard().problems());
				save(m, snapshotOut, err);
			});
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
		Path authFile;
		Path replay;
		Path mission;
		Path caseDir;
		Path queries;
		Path rules;
		Path patterns;
		boolean noDefaultPatterns;
		Path snapshotOut;
		Path record;
		Path signalsOut;
		Path utilitiesOut;
		boolean compileOnly;
		boolean untilEnd;
		boolean quiet;
		double timeoutSeconds;
		double lingerSeconds;

		static Options parse(String[] args) {
			Options o = new Options();
			boolean runGiven = false;
			for (int i = 0; i < args.length; i++) {
				String a = args[i];
				switch (a) {
				case "--until-end" -> o.untilEnd = true;
				case "--quiet" -> o.quiet = true;
				case "--no-default-patterns" -> o.noDefaultPatterns = true;
				case "--compile-only" -> o.compileOnly = true;
				case "--router", "--run", "--realm", "--auth-file", "--replay", "--mission", "--case", "--queries", "--rules", "--patterns",
						"--snapshot-out", "--record", "--signals-out", "--utilities-out", "--timeout", "--linger" -> {
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
					case "--auth-file" -> o.authFile = Path.of(v);
					case "--replay" -> o.replay = Path.of(v);
					case "--mission" -> o.mission = Path.of(v);
					case "--case" -> o.caseDir = Path.of(v);
					case "--queries" -> o.queries = Path.of(v);
					case "--rules" -> o.rules = Path.of(v);
					case "--patterns" -> o.patterns = Path.of(v);
					case "--snapshot-out" -> o.snapshotOut = Path.of(v);
					case "--record" -> o.record = Path.of(v);
					case "--signals-out" -> o.signalsOut = Path.of(v);
					case "--utilities-out" -> o.utilitiesOut = Path.of(v);
					case "--linger" -> o.lingerSeconds = seconds(a, v, true);
					default -> o.timeoutSeconds = seconds(a, v, false);
					}
				}
				default -> throw new IllegalArgumentException("unknown argument " + a);
				}
			}
			if (o.compileOnly) {
				if (o.router != null || o.replay != null) {
					throw new IllegalArgumentException("--compile-only starts neither live mode nor a replay: "
							+ "not with --router or --replay");
				}
			} else if ((o.router == null) == (o.replay == null)) {
				throw new IllegalArgumentException("give exactly one of --router and --replay");
			}
			if (o.router != null && !runGiven) {
				throw new IllegalArgumentException("live mode needs --run ID");
			}
			if (!o.run.matches(MonitorSpec.RUN_ID_PATTERN)) {
				throw new IllegalArgumentException("run id must be 1-64 characters of [A-Za-z0-9_-]: " + o.run);
			}
			if (o.replay != null && o.caseDir == null) {
				throw new IllegalArgumentException("replay needs --case DIR (world.json, monitor.json)");
			}
			if (o.replay != null) {
				String liveOnly = o.record != null ? "--record" : o.untilEnd ? "--until-end"
						: o.timeoutSeconds > 0 ? "--timeout" : o.lingerSeconds > 0 ? "--linger"
						: o.authFile != null ? "--auth-file" : null;
				if (liveOnly != null) {
					throw new IllegalArgumentException(liveOnly + " applies to live mode (--router) only");
				}
			} else if (o.mission != null) {
				throw new IllegalArgumentException("--mission applies to replay only (live: the mission topic)");
			}
			if (o.rules != null && (o.patterns != null || o.noDefaultPatterns)) {
				throw new IllegalArgumentException("--rules replaces the VEPL patterns: not with --patterns");
			}
			if (o.noDefaultPatterns && o.patterns == null) {
				throw new IllegalArgumentException("--no-default-patterns needs --patterns DIR");
			}
			if (o.lingerSeconds > 0 && !o.untilEnd) {
				throw new IllegalArgumentException("--linger needs --until-end");
			}
			return o;
		}

		private static double seconds(String option, String value, boolean zeroAllowed) {
			double v;
			try {
				v = Double.parseDouble(value);
			} catch (NumberFormatException e) {
				v = Double.NaN;
			}
			if (!Double.isFinite(v) || v < 0 || v == 0 && !zeroAllowed) {
				throw new IllegalArgumentException(option + " needs a number of seconds " + (zeroAllowed ? ">= 0" : "> 0")
						+ ", got " + value);
			}
			return v;
		}
	}
}
