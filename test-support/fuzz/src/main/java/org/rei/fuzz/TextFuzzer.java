/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.fuzz;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;

/**
 * Feeds mutated texts (seeds plus fixed special inputs, then 1-3 rounds of {@link Mutations} per input) to a
 * {@link Target}, one input at a time on a worker thread with a time limit. A failure is an exception that escapes
 * the target (an {@link AssertionError} is the target's own finding, e.g. an error placed outside the input) or an
 * input that takes longer than the limit. Deterministic for a given seed and input count.
 */
public final class TextFuzzer implements AutoCloseable {

	/** The front end under test: parses and checks one text; true when it is valid, false when refused. */
	@FunctionalInterface
	public interface Target {
		boolean check(String text) throws Exception;
	}

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

	private final Target target;
	private final List<String> seeds;
	private final List<String[]> specials;
	private final Mutations mutations;
	private final long timeoutMillis;
	private ExecutorService worker = newWorker();

	/**
	 * @param specials fixed inputs {name, text} tried before the mutated ones (shapes known to be expensive)
	 * @param mutations the generic mutations, possibly with the language's own
	 */
	public TextFuzzer(Target target, List<String> seeds, List<String[]> specials, Mutations mutations,
			long timeoutMillis) {
		this.target = target;
		this.seeds = List.copyOf(seeds);
		this.specials = List.copyOf(specials);
		this.mutations = mutations;
		this.timeoutMillis = timeoutMillis;
	}

	private static ExecutorService newWorker() {
		return Executors.newSingleThreadExecutor(r -> {
			Thread t = new Thread(r, "fuzz");
			t.setDaemon(true);
			return t;
		});
	}

	/** The texts of the files ending in {@code suffix} in each folder, sorted by name. */
	public static List<String> files(List<Path> folders, String suffix) throws IOException {
		List<String> out = new ArrayList<>();
		for (Path folder : folders) {
			try (Stream<Path> files = Files.list(folder)) {
				for (Path p : files.filter(f -> f.toString().endsWith(suffix)).sorted().toList()) {
					out.add(Files.readString(p));
				}
			}
		}
		return out;
	}

	/** The repository's root: the first folder above the working directory that has {@code marker}. */
	public static Path repositoryRoot(String marker) throws IOException {
		Path dir = Path.of("").toAbsolutePath();
		while (dir != null && !Files.isDirectory(dir.resolve(marker))) {
			dir = dir.getParent();
		}
		if (dir == null) {
			throw new IOException(marker + "/ not found above " + Path.of("").toAbsolutePath());
		}
		return dir;
	}

	/** Runs mutated inputs until {@code maxInputs} are done or {@code seconds} have passed. */
	public Result run(long seed, long maxInputs, double seconds) {
		Random random = new Random(seed);
		long deadline = System.nanoTime() + (long) (seconds * 1e9);
		List<Failure> failures = new ArrayList<>();
		Map<String, Long> byMutation = new TreeMap<>();
		long inputs = 0;
		long valid = 0;
		List<String[]> fixed = new ArrayList<>();
		for (String s : seeds) {
			fixed.add(new String[] { "seed", s });
		}
		fixed.addAll(specials);
		for (String[] f : fixed) {
			Boolean ok = check(inputs++, f[0], f[1], failures);
			byMutation.merge(f[0], 1L, Long::sum);
			valid += Boolean.TRUE.equals(ok) ? 1 : 0;
		}
		while (inputs < maxInputs && System.nanoTime() < deadline && !seeds.isEmpty()) {
			String text = seeds.get(random.nextInt(seeds.size()));
			int rounds = 1 + random.nextInt(3);
			StringBuilder names = new StringBuilder();
			for (int r = 0; r < rounds; r++) {
				String[] m = mutations.apply(text, random);
				names.append(r == 0 ? "" : "+").append(m[0]);
				text = m[1];
			}
			Boolean ok = check(inputs++, names.toString(), text, failures);
			byMutation.merge(names.toString().split("\\+")[0], 1L, Long::sum);
			valid += Boolean.TRUE.equals(ok) ? 1 : 0;
		}
		return new Result(inputs, valid, byMutation, failures);
	}

	/** Checks one input under the time limit; its validity, or null (and a failure recorded) if it failed. */
	public Boolean check(long index, String mutation, String text, List<Failure> failures) {
		Future<Boolean> f = worker.submit(() -> target.check(text));
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

	/** Asserts that an error at {@code line}:{@code column} lies inside {@code text} and says something. */
	public static void assertPlaced(String text, Integer line, Integer column, String message, Object issue) {
		if (message == null || message.isBlank()) {
			throw new AssertionError("an error without a message: " + issue);
		}
		int lines = text.split("\r\n|\r|\n", -1).length; // line breaks as Xtext and editors count them
		if (line == null || line < 1 || line > lines) {
			throw new AssertionError("error line " + line + " outside 1.." + lines + ": " + issue);
		}
		if (column == null || column < 1 || column > longestLine(text) + 2) {
			throw new AssertionError("error column " + column + " outside the input: " + issue);
		}
	}

	private static int longestLine(String text) {
		int best = 0;
		for (String line : text.split("\r\n|\r|\n", -1)) {
			best = Math.max(best, line.length());
		}
		return best;
	}

	private static String stack(Throwable t) {
		StringWriter w = new StringWriter();
		t.printStackTrace(new PrintWriter(w));
		String s = w.toString();
		return s.length() > 3000 ? s.substring(0, 3000) : s;
	}

	/** Writes the failing inputs to {@code out} and prints them; a campaign's end for a {@code main}. */
	public static void report(String language, long seed, Result r, Path out, String suffix) throws IOException {
		System.out.println(language + " fuzz, seed " + seed + ": " + r.inputs() + " inputs, " + r.valid() + " valid, "
				+ r.failures().size() + " failures; by mutation " + r.byMutation());
		if (!r.failures().isEmpty()) {
			Files.createDirectories(out);
			for (Failure f : r.failures()) {
				Path file = out.resolve(language + "-" + seed + "-" + f.index() + suffix);
				Files.writeString(file, f.input());
				System.out.println(f + "\n  input: " + file);
			}
		}
	}

	@Override
	public void close() {
		worker.shutdownNow();
	}
}
