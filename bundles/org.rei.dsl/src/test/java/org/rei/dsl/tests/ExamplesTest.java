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
import java.util.stream.Stream;

import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import com.google.inject.Inject;

/** The shipped examples and their catalogues are clean: no error and no warning. */
@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class ExamplesTest {

	@Inject
	private ReiFiles files;

	static Stream<Path> examples() throws IOException {
		return Files.walk(ReiFiles.repository().resolve("examples")).filter(p -> p.toString().endsWith(".rei"))
				.sorted();
	}

	@Test
	void thereAreExamples() throws IOException {
		assertFalse(examples().toList().isEmpty());
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("examples")
	void exampleHasNoIssues(Path example) {
		List<Issue> issues = files.validate(example);
		assertEquals(List.of(), issues, () -> example + ": " + issues);
	}
}
