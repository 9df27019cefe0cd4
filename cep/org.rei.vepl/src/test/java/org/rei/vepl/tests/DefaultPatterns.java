/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.tests;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.rei.vepl.compiler.VeplLoader;

/** The repository's cep/patterns, found from the module's working directory. */
final class DefaultPatterns {

	private DefaultPatterns() {
	}

	static Path folder() {
		Path dir = Path.of("").toAbsolutePath();
		while (dir != null && !Files.isDirectory(dir.resolve("cep/patterns"))) {
			dir = dir.getParent();
		}
		if (dir == null) {
			throw new IllegalStateException("cep/patterns not found above " + Path.of("").toAbsolutePath());
		}
		return dir.resolve("cep/patterns");
	}

	static List<VeplLoader.Source> sources() {
		try {
			return VeplLoader.folder(folder());
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}
}
