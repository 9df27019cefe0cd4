/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.fuzz;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.rei.dsl.ReiStandaloneSetup;

import com.google.inject.Injector;

/**
 * Feeds mutated .rei texts (seeds: examples/*.rei and src/test/resources/invalid/*.rei) through parse and
 * validate, one input at a time on a worker thread with a time limit. A failure is an exception that escapes,
 * an input that takes longer than the limit, or an issue without a message or with a line/column outside the
 * input. Deterministic for a given seed and input count.
 *
 * <pre>
 * mvn -B -s .mvn/settings.xml -pl bundles/org.rei.dsl test-compile
 * java -cp "bundles/org.rei.dsl/target/test-classes:bundles/org.rei.dsl/target/classes:$(cat cp.txt)" \
 *     org.rei.dsl.fuzz.DslFuzzer --seconds 600 --seed 7
 * </pre>
 */
public final class DslFuzzer implements AutoCloseable {

	/** One failing input. */
	public record Failure(long index, String mutation, String problem, String input) {
		@Override
		public String toString() {
			return "#" + index + " (" + mutation + "): " + problem;
		}
	}

	/** The outcome of a campaign. */
	public record Result(long inputs, long valid, Map<String, Long> byMutation, List<Failure> failures) {
	}

	private static final Pattern TOKEN = Pattern.compile("\"[^\"]*\"|[A-Za-z_][A-Za-z0-9_]*|-?\\d+(\\.\\d+)?|//[^\\n]*|\\S");

	private final Injector injector = new ReiStandaloneSetup().createInjectorAndDoEMFRegistration();
	private final IResourceValidator validator = injector.getInstance(IResourceValidator.class);
	private final List<String> seeds;
	private final long timeoutMillis;
	private ExecutorService worker = newWorker();
	private long counter;

	public DslFuzzer(List<String> seeds, long timeoutMillis) {
		this.seeds = List.copyOf(seeds);
		this.timeoutMillis = timeoutMillis;
	}

	private static ExecutorService newWorker() {
		return Executors.newSingleThreadExecutor(r -> {
			Thread t = new Thread(r, "dsl-fuzz");
			t.setDaemon(true);
			return t;
		});
	}

	/** The valid examples and the invalid test files, found from the module's or the repository's directory. */
	public static List<String> defaultSeeds() throws IOException {
		Path dir = Path.of("").toAbsolutePath();
		while (dir != null && !dir.resolve("examples").toFile().isDirectory()) {
			dir = dir.getParent();
		}
		if (dir == null) {
			throw new IOException("examples/ not found above " + Path.of("").toAbsolutePath());
		}
		List<String> out = new ArrayList<>();
		for (Path folder : List.of(dir.resolve("examples"), dir.resolve("bundles/org.rei.dsl/src/test/resources/invalid"))) {
			try (Stream<Path> files = Files.list(folder)) {
				for (Path p : files.filter(f -> f.toString().endsWith(".rei")).sorted().toList()) {
					out.add(Files.readString(p));
				}
			}
		}
		return out;
	}

	/** Runs mutated inputs until {@code maxInputs} are done or {@code seconds} have passed. */
	public Result run(long seed, long maxInputs, double seconds) {
		Random random = new Random(seed);
		long deadline = System.nanoTime() + (long) (seconds * 1e9);
		List<Failure> failures = new ArrayList<>();
		Map<String, Long> byMutation = new java.util.TreeMap<>();
		long inputs = 0;
		long valid = 0;
		// fixed inputs first: every seed as is, and the shapes that are known to be expensive
		List<String[]> fixed = new ArrayList<>();
		for (String s : seeds) {
			fixed.add(new String[] { "seed", s });
		}
		fixed.addAll(Mutations.specials());
		for (String[] f : fixed) {
			Boolean ok = check(inputs++, f[0], f[1], failures);
			byMutation.merge(f[0], 1L, Long::sum);
			valid += Boolean.TRUE.equals(ok) ? 1 : 0;
		}
		while (inputs < maxInputs && System.nanoTime() < deadline) {
			String base = seeds.get(random.nextInt(seeds.size()));
			int rounds = 1 + random.nextInt(3);
			StringBuilder names = new StringBuilder();
			String text = base;
			for (int r = 0; r < rounds; r++) {
				String[] m = Mutations.apply(text, random);
				names.append(r == 0 ? "" : "+").append(m[0]);
				text = m[1];
			}
			Boolean ok = check(inputs++, names.toString(), text, failures);
			byMutation.merge(names.toString().split("\\+")[0], 1L, Long::sum);
			valid += Boolean.TRUE.equals(ok) ? 1 : 0;
		}
		return new Result(inputs, valid, byMutation, failures);
	}

	/** Parses and validates one input under the time limit; true if it has no errors, null if it failed. */
	public Boolean check(long index, String mutation, String text, List<Failure> failures) {
		Future<Boolean> f = worker.submit(() -> parseAndValidate(text));
		try {
			return f.get(timeoutMillis, TimeUnit.MILLISECONDS);
		} catch (TimeoutException e) {
			f.cancel(true);
			worker.shutdownNow();
			worker = newWorker(); // the stuck thread is a daemon and abandoned
			failures.add(new Failure(index, mutation, "no result within " + timeoutMillis + " ms", text));
		} catch (ExecutionException e) {
			Throwable c = e.getCause();
			failures.add(new Failure(index, mutation, c instanceof AssertionError ? c.getMessage() : stack(c), text));
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			failures.add(new Failure(index, mutation, "interrupted", text));
		}
		return null;
	}

	private static String stack(Throwable t) {
		java.io.StringWriter w = new java.io.StringWriter();
		t.printStackTrace(new java.io.PrintWriter(w));
		String s = w.toString();
		return s.length() > 3000 ? s.substring(0, 3000) : s;
	}

	/** The issues of a text, parsed and validated as a .rei file. */
	public List<Issue> issues(String text) throws IOException {
		XtextResourceSet set = injector.getInstance(XtextResourceSet.class);
		XtextResource resource = (XtextResource) set.createResource(URI.createURI("fuzz/input" + (counter++) + ".rei"));
		resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), Map.of());
		return validator.validate(resource, CheckMode.ALL, CancelIndicator.NullImpl);
	}

	private boolean parseAndValidate(String text) throws IOException {
		List<Issue> issues = issues(text);
		int lines = 1 + (int) text.chars().filter(c -> c == '\n').count();
		boolean errors = false;
		for (Issue issue : issues) {
			if (issue.getSeverity() == org.eclipse.xtext.diagnostics.Severity.ERROR) {
				errors = true;
			}
			if (issue.getMessage() == null || issue.getMessage().isBlank()) {
				throw new AssertionError("issue without a message: " + issue);
			}
			Integer line = issue.getLineNumber();
			Integer column = issue.getColumn();
			if (line == null || line < 1 || line > lines) {
				throw new AssertionError("issue line " + line + " outside 1.." + lines + ": " + issue);
			}
			if (column == null || column < 1 || column > longestLine(text) + 2) {
				throw new AssertionError("issue column " + column + " outside the input: " + issue);
			}
		}
		return !errors;
	}

	private static int longestLine(String text) {
		int best = 0;
		int run = 0;
		for (int i = 0; i < text.length(); i++) {
			run = text.charAt(i) == '\n' ? 0 : run + 1;
			best = Math.max(best, run);
		}
		return best;
	}

	@Override
	public void close() {
		worker.shutdownNow();
	}

	/** The mutations; each returns {name, mutated text}. */
	static final class Mutations {

		private Mutations() {
		}

		static List<String[]> specials() {
			List<String[]> out = new ArrayList<>();
			String robotTail = "    robot r : Waffle on F_0_0\n  }\n  mission M { goto F_1_1 goto F_2_2 }\n}\n";
			out.add(new String[] { "big-grid", "testcase T {\n  room R size 100 x 100 {\n" + robotTail });
			out.add(new String[] { "limit-grid", "testcase T {\n  room R size 200 x 200 {\n" + robotTail });
			out.add(new String[] { "over-limit-grid", "testcase T {\n  room R size 201 x 200 {\n" + robotTail });
			out.add(new String[] { "huge-grid", "testcase T {\n  room R size 100000 x 100000 {\n" + robotTail });
			out.add(new String[] { "max-grid", "testcase T {\n  room R size 2147483647 x 2147483647 {\n" + robotTail });
			out.add(new String[] { "int-overflow", "testcase T {\n  room R size 99999999999999999999 x 3 {\n" + robotTail });
			StringBuilder map = new StringBuilder("testcase T {\n  room R map \"\n");
			for (int y = 0; y < 100; y++) {
				map.append(".".repeat(100)).append('\n');
			}
			out.add(new String[] { "big-map", map + "\" {\n" + robotTail });
			String wide = "testcase T {\n  room R map \"\n" + ".".repeat(20000) + "\n" + "\n".repeat(20000) + ".\n\" {\n"
					+ robotTail;
			out.add(new String[] { "sparse-map", wide });
			out.add(new String[] { "huge-number", "testcase T {\n  room R size 3 x 3 floorSize "
					+ "9".repeat(400) + ".5 {\n" + robotTail });
			out.add(new String[] { "deep-nesting", "testcase T {\n" + "{".repeat(5000) + "}".repeat(5000) + "\n}\n" });
			out.add(new String[] { "long-name", "testcase " + "N".repeat(200_000) + " {\n  room R size 3 x 3 {\n" + robotTail });
			out.add(new String[] { "empty", "" });
			out.add(new String[] { "nul", "\0\0\0" });
			return out;
		}

		static String[] apply(String text, Random r) {
			switch (r.nextInt(12)) {
			case 0: {
				if (text.isEmpty()) {
					return new String[] { "flip", text };
				}
				char[] c = text.toCharArray();
				int n = 1 + r.nextInt(4);
				for (int i = 0; i < n; i++) {
					int at = r.nextInt(c.length);
					c[at] = (char) (c[at] ^ (1 << r.nextInt(8)));
				}
				return new String[] { "flip", new String(c) };
			}
			case 1:
				return new String[] { "truncate", text.substring(0, r.nextInt(text.length() + 1)) };
			case 2:
			case 3:
			case 4: {
				List<String> tokens = tokens(text);
				if (tokens.size() < 2) {
					return new String[] { "tokens", text };
				}
				int i = r.nextInt(tokens.size());
				int j = r.nextInt(tokens.size());
				String name;
				switch (r.nextInt(3)) {
				case 0 -> {
					tokens.remove(i);
					name = "token-delete";
				}
				case 1 -> {
					tokens.add(i, tokens.get(j));
					name = "token-duplicate";
				}
				default -> {
					String t = tokens.get(i);
					tokens.set(i, tokens.get(j));
					tokens.set(j, t);
					name = "token-swap";
				}
				}
				return new String[] { name, String.join(" ", tokens) };
			}
			case 5:
				return replaceNumber(text, r, new String[] { "99999999999999999999", "2147483647", "-2147483648",
						"1" + "0".repeat(400), "0", "-0", "100000", "0.00000000000000000001", "1.7976931348623157",
						"-1" });
			case 6:
				return replaceName(text, r, new String[] { "X".repeat(10_000 + r.nextInt(50_000)), "s", "x", "é_ü",
						"\u0000", "\uD83D\uDE00", "\uD800", "ab\u202Ecd", "𝔘𝔫𝔦𝔠𝔬𝔡𝔢" });
			case 7: {
				int at = text.isEmpty() ? 0 : r.nextInt(text.length());
				String[] junk = { "\0", "\uFEFF", "\uFFFF", "\uD800", "\"", "//", "/*", "{", "}", "[", "]", "@", "\r",
						"\t\u00A0", "'", "\\" };
				return new String[] { "insert", text.substring(0, at) + junk[r.nextInt(junk.length)] + text.substring(at) };
			}
			case 8: {
				int at = text.isEmpty() ? 0 : r.nextInt(text.length());
				int depth = 1 + r.nextInt(3000);
				String open = r.nextBoolean() ? "{" : "[";
				return new String[] { "nest", text.substring(0, at) + open.repeat(depth) + text.substring(at) };
			}
			case 9: {
				String size = (1 + r.nextInt(120)) + " x " + (1 + r.nextInt(120));
				return new String[] { "resize", text.replaceAll("size \\d+ x \\d+", "size " + size) };
			}
			case 10: {
				if (text.isEmpty()) {
					return new String[] { "splice", text };
				}
				int a = r.nextInt(text.length());
				int b = Math.min(text.length(), a + r.nextInt(200));
				int at = r.nextInt(text.length());
				return new String[] { "splice", text.substring(0, at) + text.substring(a, b) + text.substring(at) };
			}
			default: {
				// byte-level: re-decode mutated UTF-8, as a file with broken encoding would be read
				byte[] b = text.getBytes(StandardCharsets.UTF_8);
				if (b.length > 0) {
					b[r.nextInt(b.length)] = (byte) r.nextInt(256);
				}
				return new String[] { "bytes", new String(b, StandardCharsets.UTF_8) };
			}
			}
		}

		private static List<String> tokens(String text) {
			List<String> out = new ArrayList<>();
			Matcher m = TOKEN.matcher(text);
			while (m.find()) {
				out.add(m.group());
			}
			return out;
		}

		private static String[] replaceNumber(String text, Random r, String[] values) {
			List<int[]> spans = spans(Pattern.compile("\\d+(\\.\\d+)?"), text);
			if (spans.isEmpty()) {
				return new String[] { "number", text };
			}
			int[] s = spans.get(r.nextInt(spans.size()));
			return new String[] { "number",
					text.substring(0, s[0]) + values[r.nextInt(values.length)] + text.substring(s[1]) };
		}

		private static String[] replaceName(String text, Random r, String[] values) {
			List<int[]> spans = spans(Pattern.compile("\\b[A-Za-z_][A-Za-z0-9_]*\\b"), text);
			if (spans.isEmpty()) {
				return new String[] { "name", text };
			}
			int[] s = spans.get(r.nextInt(spans.size()));
			return new String[] { "name", text.substring(0, s[0]) + values[r.nextInt(values.length)] + text.substring(s[1]) };
		}

		private static List<int[]> spans(Pattern p, String text) {
			List<int[]> out = new ArrayList<>();
			Matcher m = p.matcher(text);
			while (m.find()) {
				out.add(new int[] { m.start(), m.end() });
			}
			return out;
		}
	}

	/** {@code --seconds N --seed S [--inputs N] [--timeout-ms N] [--out DIR]}: a longer campaign; exit 1 on failures. */
	public static void main(String[] args) throws IOException {
		double seconds = 60;
		long seed = System.nanoTime();
		long inputs = Long.MAX_VALUE;
		long timeout = 10_000;
		Path out = Path.of("target/fuzz-failures");
		for (int i = 0; i + 1 < args.length; i += 2) {
			switch (args[i]) {
			case "--seconds" -> seconds = Double.parseDouble(args[i + 1]);
			case "--seed" -> seed = Long.parseLong(args[i + 1]);
			case "--inputs" -> inputs = Long.parseLong(args[i + 1]);
			case "--timeout-ms" -> timeout = Long.parseLong(args[i + 1]);
			case "--out" -> out = Path.of(args[i + 1]);
			default -> throw new IllegalArgumentException("unknown option " + args[i]);
			}
		}
		try (DslFuzzer fuzzer = new DslFuzzer(defaultSeeds(), timeout)) {
			Result r = fuzzer.run(seed, inputs, seconds);
			System.out.println("seed " + seed + ": " + r.inputs() + " inputs, " + r.valid() + " valid, "
					+ r.failures().size() + " failures; by mutation " + r.byMutation());
			if (!r.failures().isEmpty()) {
				Files.createDirectories(out);
				for (Failure f : r.failures()) {
					Path file = out.resolve("dsl-" + seed + "-" + f.index() + ".rei");
					Files.writeString(file, f.input());
					System.out.println(f + "\n  input: " + file);
				}
				System.exit(1);
			}
		}
		System.exit(0);
	}
}
