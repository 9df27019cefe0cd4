/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.rei.context.TestCase;

/** Files of the repository and the assertions the editing tests share. */
public final class Texts {

	private Texts() {
	}

	/** Repository root, found from the module's working directory. */
	public static Path repository() {
		Path dir = Path.of("").toAbsolutePath();
		while (dir != null && !dir.resolve("examples").toFile().isDirectory()) {
			dir = dir.getParent();
		}
		if (dir == null) {
			throw new IllegalStateException("examples/ not found above " + Path.of("").toAbsolutePath());
		}
		return dir;
	}

	static RoomDocument open(String path) {
		try {
			return RoomDocument.open(repository().resolve(path));
		} catch (IOException e) {
			throw new IllegalStateException(e);
		}
	}

	/**
	 * The lines that differ, as the body of a unified diff without context lines: "-old" and "+new" lines in text
	 * order (longest common subsequence of lines; the files here are small).
	 */
	static List<String> diff(String before, String after) {
		List<String> a = before.lines().toList();
		List<String> b = after.lines().toList();
		int[][] common = new int[a.size() + 1][b.size() + 1];
		for (int i = a.size() - 1; i >= 0; i--) {
			for (int j = b.size() - 1; j >= 0; j--) {
				common[i][j] = a.get(i).equals(b.get(j)) ? common[i + 1][j + 1] + 1
						: Math.max(common[i + 1][j], common[i][j + 1]);
			}
		}
		List<String> result = new ArrayList<>();
		int i = 0;
		int j = 0;
		while (i < a.size() || j < b.size()) {
			if (i < a.size() && j < b.size() && a.get(i).equals(b.get(j))) {
				i++;
				j++;
			} else if (j < b.size() && (i == a.size() || common[i][j + 1] > common[i + 1][j])) {
				result.add("+" + b.get(j++));
			} else {
				result.add("-" + a.get(i++));
			}
		}
		return result;
	}

	/**
	 * Independent of the document's own check: the same operations applied straight to a freshly parsed model (no
	 * serializer involved) give a model equal to what the written text parses to.
	 */
	static void assertReadsBackAsEdited(String originalText, URI uri, String writtenText, EditOperation... operations) {
		RoomDocument expected = RoomDocument.of(uri, originalText);
		TestCase model = expected.model();
		for (EditOperation operation : operations) {
			// one editor per operation: one editor refuses to change what its batch added (the document splits such
			// a batch)
			new ModelEditor(model, RoomEditSetup.injector().getInstance(IScopeProvider.class), java.util.Set.of())
					.apply(operation);
		}
		TestCase written = RoomDocument.of(uri, writtenText).model();
		assertTrue(new EcoreUtil.EqualityHelper().equals(model, written), "the written text reads back differently");
		assertEquals(org.rei.dsl.edit.diagram.DiagramBuilder.of(model), org.rei.dsl.edit.diagram.DiagramBuilder
				.of(written));
	}
}
