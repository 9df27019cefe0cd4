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
final class Texts {

	private Texts() {
	}

	/** Repository root, found from the module's working directory. */
	static Path repository() {
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
	 * The lines that differ, as a unified diff's body without context: the common leading and trailing lines are
	 * dropped, what remains is "-old" lines then "+new" lines.
	 */
	static List<String> diff(String before, String after) {
		List<String> a = before.lines().toList();
		List<String> b = after.lines().toList();
		int head = 0;
		while (head < a.size() && head < b.size() && a.get(head).equals(b.get(head))) {
			head++;
		}
		int tail = 0;
		while (tail < a.size() - head && tail < b.size() - head
				&& a.get(a.size() - 1 - tail).equals(b.get(b.size() - 1 - tail))) {
			tail++;
		}
		List<String> result = new ArrayList<>();
		a.subList(head, a.size() - tail).forEach(line -> result.add("-" + line));
		b.subList(head, b.size() - tail).forEach(line -> result.add("+" + line));
		return result;
	}

	/**
	 * Independent of the document's own check: the same operations applied straight to a freshly parsed model (no
	 * serializer involved) give a model equal to what the written text parses to.
	 */
	static void assertReadsBackAsEdited(String originalText, URI uri, String writtenText, EditOperation... operations) {
		RoomDocument expected = RoomDocument.of(uri, originalText);
		TestCase model = expected.model();
		ModelEditor editor = new ModelEditor(model, RoomEditSetup.injector().getInstance(IScopeProvider.class),
				java.util.Set.of());
		for (EditOperation operation : operations) {
			editor.apply(operation);
		}
		TestCase written = RoomDocument.of(uri, writtenText).model();
		assertTrue(new EcoreUtil.EqualityHelper().equals(model, written), "the written text reads back differently");
		assertEquals(org.rei.dsl.edit.diagram.DiagramBuilder.of(model), org.rei.dsl.edit.diagram.DiagramBuilder
				.of(written));
	}
}
