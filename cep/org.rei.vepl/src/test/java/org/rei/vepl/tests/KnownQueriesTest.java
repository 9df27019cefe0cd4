/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.rei.vepl.validation.KnownQueries;
import org.rei.vepl.validation.VeplIssueCodes;

import com.google.inject.Inject;
import com.google.inject.Provider;

/**
 * The queries a file loaded from disk may name, as an editor checks them: what the monitor would load, the default
 * queries (packaged from the repository's queries/) plus those of the nearest queries/ folder above the file. The
 * files here lie outside the repository, as a user's workspace does.
 */
@ExtendWith(InjectionExtension.class)
@InjectWith(VeplInjectorProvider.class)
class KnownQueriesTest {

	private static final String PATTERNS = """
			queryEvent closeFound as robotClose found
			queryEvent mineFound as myQuery found
			queryEvent nearFound as robotNear found
			""";

	@Inject
	private Provider<XtextResourceSet> resourceSets;

	@Inject
	private IResourceValidator validator;

	@TempDir
	Path tmp;

	/** Each error as {@code line:column code message}. */
	private List<String> errors(Path file) {
		var r = resourceSets.get().getResource(URI.createFileURI(file.toAbsolutePath().toString()), true);
		return validator.validate(r, CheckMode.ALL, CancelIndicator.NullImpl).stream()
				.filter(i -> i.getSeverity() == Severity.ERROR)
				.map(i -> i.getLineNumber() + ":" + i.getColumn() + " " + i.getCode() + " " + i.getMessage()).toList();
	}

	private static String unknown(int line, String name, Set<String> known) {
		return line + ":25 " + VeplIssueCodes.UNKNOWN_QUERY + " Unknown query '" + name
				+ "': the loaded queries are " + String.join(", ", known);
	}

	@Test
	void theDefaultsAreTheQueriesOfTheRepositorysQueriesFolder() {
		assertEquals(KnownQueries.inFolder(DefaultPatterns.folder().resolve("../../queries").normalize()),
				KnownQueries.defaults());
	}

	@Test
	void aFileWithNoQueriesFolderAboveItKnowsTheDefaultQueries() throws IOException {
		for (Path dir = tmp; dir != null; dir = dir.getParent()) {
			assertFalse(Files.isDirectory(dir.resolve("queries")), "the test needs no queries/ above " + tmp);
		}
		Path file = Files.writeString(tmp.resolve("p.vepl"), PATTERNS);
		Set<String> defaults = KnownQueries.defaults();
		assertEquals(List.of(unknown(2, "myQuery", defaults), unknown(3, "robotNear", defaults)), errors(file));
	}

	@Test
	void aFileUnderItsOwnQueriesFolderKnowsTheDefaultsAndItsOwn() throws IOException {
		Files.createDirectories(tmp.resolve("queries"));
		Files.writeString(tmp.resolve("queries/mine.drl"), "query myQuery(String subject)\nend\n");
		Path file = Files.writeString(Files.createDirectories(tmp.resolve("patterns")).resolve("p.vepl"), PATTERNS);
		Set<String> known = new TreeSet<>(KnownQueries.defaults());
		known.add("myQuery");
		assertEquals(List.of(unknown(3, "robotNear", known)), errors(file));
	}
}
