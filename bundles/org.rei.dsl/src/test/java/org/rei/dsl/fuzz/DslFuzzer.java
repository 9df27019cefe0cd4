/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.fuzz;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.rei.dsl.ReiStandaloneSetup;
import org.rei.fuzz.Mutations;
import org.rei.fuzz.TextFuzzer;

import com.google.inject.Injector;

/**
 * The DSL's front end under {@link TextFuzzer} (test-support/fuzz): mutated .rei texts (seeds: examples/*.rei and
 * src/test/resources/invalid/*.rei) are parsed and validated; a failure is an exception that escapes, an input
 * that takes longer than the limit, or an issue without a message or with a line/column outside the input.
 * Deterministic for a given seed and input count.
 *
 * <pre>
 * mvn -B -s .mvn/settings.xml -pl bundles/org.rei.dsl test-compile
 * java -cp "bundles/org.rei.dsl/target/test-classes:bundles/org.rei.dsl/target/classes:$(cat cp.txt)" \
 *     org.rei.dsl.fuzz.DslFuzzer --seconds 600 --seed 7
 * </pre>
 */
public final class DslFuzzer implements AutoCloseable {

	private final Injector injector = new ReiStandaloneSetup().createInjectorAndDoEMFRegistration();
	private final IResourceValidator validator = injector.getInstance(IResourceValidator.class);
	private final TextFuzzer fuzzer;
	private long counter;

	public DslFuzzer(List<String> seeds, long timeoutMillis) {
		this.fuzzer = new TextFuzzer(this::parseAndValidate, seeds, Specials.specials(),
				new Mutations(DslFuzzer::resize), timeoutMillis);
	}

	/** The valid examples and the invalid test files, found from the module's or the repository's directory. */
	public static List<String> defaultSeeds() throws IOException {
		Path root = TextFuzzer.repositoryRoot("examples");
		return TextFuzzer.files(List.of(root.resolve("examples"), root.resolve("bundles/org.rei.dsl/src/test/resources/invalid")),
				".rei");
	}

	public TextFuzzer.Result run(long seed, long maxInputs, double seconds) {
		return fuzzer.run(seed, maxInputs, seconds);
	}

	/** The DSL's own mutation: another room size. */
	private static String[] resize(String text, Random r) {
		String size = (1 + r.nextInt(120)) + " x " + (1 + r.nextInt(120));
		return new String[] { "resize", text.replaceAll("size \\d+ x \\d+", "size " + size) };
	}

	/** The issues of a text, parsed and validated as a .rei file. */
	public List<Issue> issues(String text) throws IOException {
		XtextResourceSet set = injector.getInstance(XtextResourceSet.class);
		XtextResource resource = (XtextResource) set.createResource(URI.createURI("fuzz/input" + (counter++) + ".rei"));
		resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), Map.of());
		return validator.validate(resource, CheckMode.ALL, CancelIndicator.NullImpl);
	}

	private boolean parseAndValidate(String text) throws IOException {
		boolean errors = false;
		for (Issue issue : issues(text)) {
			errors |= issue.getSeverity() == org.eclipse.xtext.diagnostics.Severity.ERROR;
			TextFuzzer.assertPlaced(text, issue.getLineNumber(), issue.getColumn(), issue.getMessage(), issue);
		}
		return !errors;
	}

	@Override
	public void close() {
		fuzzer.close();
	}

	/** Fixed inputs of shapes known to be expensive for the DSL. */
	static final class Specials {

		private Specials() {
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
			TextFuzzer.Result r = fuzzer.run(seed, inputs, seconds);
			TextFuzzer.report("dsl", seed, r, out, ".rei");
			System.exit(r.failures().isEmpty() ? 0 : 1);
		}
	}
}
