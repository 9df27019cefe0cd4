/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.nio.file.Path;

/**
 * How an {@link ArtifactGenerator} is set up.
 *
 * @param templateOverrides a folder whose {@code *.egl} files replace the built-in templates of the same name
 *                          (e.g. {@code world.sdf.egl}); {@code null} to use the built-in ones only
 */
public record GeneratorOptions(Path templateOverrides) {

	/** Built-in templates only. */
	public static GeneratorOptions defaults() {
		return new GeneratorOptions(null);
	}
}
