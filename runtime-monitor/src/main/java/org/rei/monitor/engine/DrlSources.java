/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystem;
import java.nio.file.FileSystemAlreadyExistsException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/**
 * The .drl files the session is built from: every {@code *.drl} of a folder given on the command line, or the
 * copies of {@code queries/} and the rules compiled from {@code cep/patterns/} packaged in the jar. Sorted by name,
 * so builds are repeatable.
 */
public final class DrlSources {

	/** Classpath folder of the packaged queries (a copy of the repository's {@code queries/}). */
	public static final String QUERIES = "/org/rei/monitor/queries";
	/** Classpath folder of the transition rules the build compiled from {@code cep/patterns/} (see PatternRules). */
	public static final String RULES = "/org/rei/monitor/rules";

	/** One rule file: where it came from (for error messages) and its text. */
	public record Source(String path, String text) {
	}

	private DrlSources() {
	}

	public static List<Source> folder(Path dir) throws IOException {
		if (!Files.isDirectory(dir)) {
			throw new IOException("not a folder of .drl files: " + dir);
		}
		List<Source> out = new ArrayList<>();
		try (Stream<Path> files = Files.list(dir)) {
			for (Path p : files.filter(f -> f.getFileName().toString().endsWith(".drl"))
					.sorted(Comparator.comparing(f -> f.getFileName().toString())).toList()) {
				out.add(new Source(p.toString(), Files.readString(p, StandardCharsets.UTF_8)));
			}
		}
		if (out.isEmpty()) {
			throw new IOException("no .drl files in " + dir);
		}
		return out;
	}

	/** The packaged copies in {@code classpathFolder} (a folder of the classes directory or of the jar). */
	public static List<Source> packaged(String classpathFolder) {
		try {
			return folder(packagedFolder(classpathFolder, "rules"));
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}

	/**
	 * A folder of the classpath as a {@link Path}: in the classes directory (builds, tests) or inside the jar (a zip
	 * file system, opened once and shared). {@code what} names its content in the error when it is missing.
	 */
	static Path packagedFolder(String classpathFolder, String what) throws IOException {
		URL url = DrlSources.class.getResource(classpathFolder);
		if (url == null) {
			throw new IllegalStateException("packaged " + what + " missing: " + classpathFolder);
		}
		try {
			URI uri = url.toURI();
			if (!"jar".equals(uri.getScheme())) {
				return Path.of(uri);
			}
			FileSystem fs;
			try {
				fs = FileSystems.newFileSystem(uri, Map.of());
			} catch (FileSystemAlreadyExistsException e) {
				fs = FileSystems.getFileSystem(uri);
			}
			return fs.getPath(classpathFolder);
		} catch (URISyntaxException e) {
			throw new IllegalStateException(e);
		}
	}
}
