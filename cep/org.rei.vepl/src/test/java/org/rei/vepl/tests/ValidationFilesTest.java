/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import com.google.inject.Inject;
import com.google.inject.Provider;

/**
 * One invalid file per rule under src/test/resources/invalid, loaded from disk (so the queries are those of the
 * repository's queries/ folder). Header lines {@code // expect: LINE:COLUMN CODE | message fragment} list every
 * error; a missing, misplaced or extra error fails.
 */
@ExtendWith(InjectionExtension.class)
@InjectWith(VeplInjectorProvider.class)
class ValidationFilesTest {

	private static final Pattern EXPECT = Pattern.compile("^// expect: (\\d+):(\\d+) (\\S+) \\| (.+)$");

	@Inject
	private Provider<XtextResourceSet> resourceSets;

	@Inject
	private IResourceValidator validator;

	static Stream<Path> invalidFiles() throws IOException {
		return Files.list(Path.of("src/test/resources/invalid")).filter(p -> p.toString().endsWith(".vepl")).sorted();
	}

	private List<Issue> errors(Path file) {
		var r = resourceSets.get().getResource(URI.createFileURI(file.toAbsolutePath().toString()), true);
		return validator.validate(r, CheckMode.ALL, CancelIndicator.NullImpl).stream()
				.filter(i -> i.getSeverity() == Severity.ERROR).toList();
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("invalidFiles")
	void reportsExactlyTheExpectedErrors(Path file) throws IOException {
		List<String> lines = Files.readAllLines(file);
		List<String> expected = lines.stream().map(EXPECT::matcher).filter(Matcher::matches)
				.map(m -> m.group(1) + ":" + m.group(2) + " " + m.group(3)).sorted().toList();
		assertFalse(expected.isEmpty(), "no '// expect:' line in " + file);
		List<Issue> errors = errors(file);
		List<String> actual = errors.stream().map(i -> i.getLineNumber() + ":" + i.getColumn() + " " + i.getCode())
				.sorted().toList();
		assertEquals(expected, actual, () -> "errors of " + file + ": " + errors);
		for (String line : lines) {
			Matcher m = EXPECT.matcher(line);
			if (m.matches()) {
				assertTrue(errors.stream().anyMatch(i -> i.getLineNumber() == Integer.parseInt(m.group(1))
						&& i.getMessage().contains(m.group(4))),
						() -> "no error on line " + m.group(1) + " saying '" + m.group(4) + "': " + errors);
			}
		}
	}

	@Test
	void theDefaultPatternsHaveNoIssuesAtAll() throws IOException {
		try (Stream<Path> files = Files.list(DefaultPatterns.folder())) {
			for (Path p : files.filter(f -> f.toString().endsWith(".vepl")).toList()) {
				var set = resourceSets.get();
				var r = set.getResource(URI.createFileURI(p.toAbsolutePath().toString()), true);
				assertEquals(List.of(), validator.validate(r, CheckMode.ALL, CancelIndicator.NullImpl), p.toString());
			}
		}
	}
}
