/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import com.google.inject.Inject;

/**
 * One invalid file per rule under src/test/resources/invalid. Each file states the errors it must produce in
 * header lines {@code // expect: LINE:COLUMN CODE | message fragment}; the test fails on a missing error, on a
 * wrong position, code or message, and on any error not listed.
 */
@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class ValidationFilesTest {

	private static final Pattern EXPECT = Pattern.compile("^// expect: (\\d+):(\\d+) (\\S+) \\| (.+)$");

	@Inject
	private ReiFiles files;

	static Stream<Path> invalidFiles() throws IOException {
		return Files.list(Path.of("src/test/resources/invalid")).filter(p -> p.toString().endsWith(".rei")).sorted();
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("invalidFiles")
	void reportsExactlyTheExpectedErrors(Path file) throws IOException {
		List<String> expected = Files.readAllLines(file).stream().map(EXPECT::matcher).filter(Matcher::matches)
				.map(m -> m.group(1) + ":" + m.group(2) + " " + m.group(3)).sorted().toList();
		assertFalse(expected.isEmpty(), "no '// expect:' line in " + file);
		List<Issue> errors = files.validate(file).stream().filter(i -> i.getSeverity() == Severity.ERROR).toList();
		List<String> actual = errors.stream().map(i -> i.getLineNumber() + ":" + i.getColumn() + " " + i.getCode())
				.sorted().toList();
		assertEquals(expected, actual, () -> "errors of " + file + ": " + errors);

		for (String line : Files.readAllLines(file)) {
			Matcher m = EXPECT.matcher(line);
			if (m.matches()) {
				String fragment = m.group(4);
				boolean found = errors.stream().anyMatch(i -> i.getLineNumber() == Integer.parseInt(m.group(1))
						&& i.getMessage().contains(fragment));
				assertEquals(true, found, () -> "no error on line " + m.group(1) + " saying '" + fragment + "': " + errors);
			}
		}
	}
}
