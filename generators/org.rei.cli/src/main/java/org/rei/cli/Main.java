/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;

import org.rei.warmjvm.CommandServer;

/**
 * {@code rei-cli validate FILE...}, {@code rei-cli generate FILE -o DIR [--templates DIR]} and
 * {@code rei-cli types CATALOGUE} (a user catalogue's types as JSON on standard output).
 * Exit codes: 0 fine, 1 the test case has errors, 2 the command itself is wrong or a file cannot be read or written.
 */
public final class Main {

	static final int OK = 0;
	static final int INVALID = 1;
	static final int USAGE = 2;

	private static final String USAGE_TEXT = """
			usage: rei-cli validate FILE.rei [FILE.rei ...] [--quiet] [--repeat N]
			       rei-cli generate FILE.rei -o OUTDIR [--templates DIR] [--quiet] [--repeat N]
			       rei-cli types CATALOGUE.rei   (its object and robot types as JSON)
			       rei-cli --serve SOCKET        (run many of the above in this JVM: org.rei.warmjvm)
			  --templates DIR  EGL templates in DIR replace the built-in ones of the same name
			  --repeat N       run N times in one process and print each run's time (for benchmarks)
			  --quiet          print diagnostics only
			exit codes: 0 ok, 1 the test case has errors, 2 bad command or unreadable/unwritable files""";

	/** The code of a file's diagnostic when checking it failed unexpectedly (a bug of REI's, not of the file). */
	static final String INTERNAL_ERROR = "org.rei.cli.internalError";

	private final PrintStream out;
	private final PrintStream err;
	private final Function<Path, HeadlessGenerator> generators;

	Main(PrintStream out, PrintStream err) {
		this(out, err, HeadlessGenerator::new);
	}

	/** {@code generators}: the generator for the {@code --templates} folder (or null); tests give their own. */
	Main(PrintStream out, PrintStream err, Function<Path, HeadlessGenerator> generators) {
		this.out = out;
		this.err = err;
		this.generators = generators;
	}

	public static void main(String[] args) {
		if (args.length == 2 && args[0].equals("--serve")) { // a warm JVM for many commands (org.rei.warmjvm)
			System.exit(CommandServer.serveUntilStdinCloses((a, out, err) -> new Main(out, err).run(a), args[1],
					System.err));
		}
		System.exit(new Main(System.out, System.err).run(args));
	}

	int run(String[] args) {
		Options options;
		try {
			options = Options.parse(args);
		} catch (IllegalArgumentException e) {
			err.println("rei-cli: " + e.getMessage());
			err.println(USAGE_TEXT);
			return USAGE;
		}
		if (options.help) {
			out.println(USAGE_TEXT);
			return OK;
		}
		for (Path file : options.files) {
			if (!Files.isRegularFile(file) || !Files.isReadable(file)) {
				err.println("rei-cli: cannot read " + file + ": no such file");
				return USAGE;
			}
		}
		HeadlessGenerator generator = generators.apply(options.templates);
		if (options.command.equals("types")) {
			HeadlessGenerator.CatalogueResult result = generator.describeCatalogue(options.files.get(0));
			result.diagnostics().forEach(err::println);
			if (result.json() == null) {
				return INVALID;
			}
			out.println(result.json());
			return OK;
		}
		int status = OK;
		for (int iteration = 1; iteration <= options.repeat; iteration++) {
			long start = System.nanoTime();
			status = runOnce(generator, options, iteration == options.repeat);
			if (options.repeat > 1) {
				out.printf(Locale.ROOT, "iteration %d: %.1f ms%n", iteration, (System.nanoTime() - start) / 1e6);
			}
			if (status == USAGE) {
				break;
			}
		}
		return status;
	}

	private int runOnce(HeadlessGenerator generator, Options options, boolean report) {
		int status = OK;
		for (Path file : options.files) {
			HeadlessGenerator.Result result;
			try {
				result = options.command.equals("generate") ? generator.generate(file, options.output)
						: generator.validate(file);
			} catch (IOException e) {
				err.println("rei-cli: cannot write " + options.output + ": " + e.getMessage());
				return USAGE;
			} catch (RuntimeException | StackOverflowError | OutOfMemoryError e) {
				// one file's failure is that file's error: the other files of the same call are still checked
				result = new HeadlessGenerator.Result(List.of(internalError(file, e)), List.of());
			}
			if (report) {
				result.diagnostics().forEach(err::println);
				if (!options.quiet) {
					result.written().forEach(path -> out.println("wrote " + path));
				}
			}
			if (result.hasErrors()) {
				status = INVALID;
			}
		}
		if (report && !options.quiet && status == OK && options.command.equals("validate")) {
			out.println(options.files.size() == 1 ? options.files.get(0) + " is valid"
					: options.files.size() + " files are valid");
		}
		return status;
	}

	/** An unexpected failure as the file's diagnostic, with where it happened, for a bug report. */
	static Diagnostic internalError(Path file, Throwable e) {
		StackTraceElement[] trace = e.getStackTrace();
		return new Diagnostic(file, 1, 1, Diagnostic.Severity.ERROR, "internal error while checking this file, "
				+ "please report it: " + e + (trace.length > 0 ? " at " + trace[0] : ""), INTERNAL_ERROR);
	}

	/** The parsed command line. */
	private static final class Options {
		String command;
		final List<Path> files = new ArrayList<>();
		Path output;
		Path templates;
		boolean quiet;
		boolean help;
		int repeat = 1;

		static Options parse(String[] args) {
			Options o = new Options();
			for (int i = 0; i < args.length; i++) {
				String arg = args[i];
				switch (arg) {
				case "-h", "--help" -> o.help = true;
				case "-q", "--quiet" -> o.quiet = true;
				case "-o", "--output" -> o.output = Path.of(value(args, ++i, arg));
				case "--templates" -> o.templates = Path.of(value(args, ++i, arg));
				case "--repeat" -> o.repeat = positive(value(args, ++i, arg), arg);
				default -> {
					if (arg.startsWith("-")) {
						throw new IllegalArgumentException("unknown option " + arg);
					} else if (o.command == null) {
						o.command = arg;
					} else {
						o.files.add(Path.of(arg));
					}
				}
				}
			}
			if (o.help) {
				return o;
			}
			if (o.command == null || !List.of("validate", "generate", "types").contains(o.command)) {
				throw new IllegalArgumentException(o.command == null ? "expected a command"
						: "unknown command '" + o.command + "': expected validate, generate or types");
			}
			if (o.files.isEmpty()) {
				throw new IllegalArgumentException("expected a .rei file");
			}
			for (Path file : o.files) {
				if (!file.toString().endsWith(".rei")) {
					throw new IllegalArgumentException("expected a .rei file, got " + file);
				}
			}
			if (o.command.equals("types") && o.files.size() != 1) {
				throw new IllegalArgumentException("types takes one catalogue file");
			}
			if (o.command.equals("generate")) {
				if (o.output == null) {
					throw new IllegalArgumentException("generate needs an output folder: -o OUTDIR");
				}
				if (o.files.size() != 1) {
					throw new IllegalArgumentException("generate takes one .rei file");
				}
			}
			if (o.templates != null && !Files.isDirectory(o.templates)) {
				throw new IllegalArgumentException("--templates " + o.templates + " is not a folder");
			}
			return o;
		}

		private static String value(String[] args, int i, String option) {
			if (i >= args.length) {
				throw new IllegalArgumentException(option + " needs a value");
			}
			return args[i];
		}

		private static int positive(String text, String option) {
			try {
				int n = Integer.parseInt(text);
				if (n >= 1) {
					return n;
				}
			} catch (NumberFormatException e) {
				// reported below
			}
			throw new IllegalArgumentException(option + " expects a whole number of at least 1, got " + text);
		}
	}
}
