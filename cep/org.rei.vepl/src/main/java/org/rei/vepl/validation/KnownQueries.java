/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.validation;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.FileSystem;
import java.nio.file.FileSystemAlreadyExistsException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.emf.common.notify.impl.AdapterImpl;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;

/**
 * The DRL queries a queryEvent may name. Whoever loads the files (the compiler, the monitor) attaches the names of
 * the queries it will run to the resource set. Without that (an editor) they are what the monitor would load: the
 * default queries, packaged in this jar from the repository's {@code queries/} by the build, plus those of the
 * nearest {@code queries/} folder above the file (the user's own, as {@code --queries DIR}).
 */
public final class KnownQueries extends AdapterImpl {

	private static final Pattern QUERY = Pattern.compile("(?m)^\\s*query\\s+([A-Za-z_$][\\w$]*)");

	/** Classpath folder of the default queries (a copy of the repository's {@code queries/}, see the pom). */
	public static final String DEFAULTS = "/org/rei/vepl/queries";

	/**
	 * The query names of the thesis's own patterns (9.2.2.1) and REI's state queries they stand for
	 * (queries/robot-state.drl), so the appendix compiles as printed.
	 */
	public static final Map<String, String> THESIS_NAMES = Map.of("findFarObject", "robotFar", "findCloseToObject",
			"robotClose", "findCollisionToObject", "robotInCollision");

	/** The query a query event names: itself, or REI's for one of the thesis's names. */
	public static String resolve(String name) {
		return THESIS_NAMES.getOrDefault(name, name);
	}

	private final Set<String> names;

	public KnownQueries(Set<String> names) {
		this.names = Set.copyOf(names);
	}

	public Set<String> names() {
		return names;
	}

	public static void attach(ResourceSet set, Set<String> names) {
		set.eAdapters().removeIf(a -> a instanceof KnownQueries);
		set.eAdapters().add(new KnownQueries(names));
	}

	/**
	 * The known names for a resource: those attached to its resource set, else (sorted) the default queries plus
	 * those of the nearest {@code queries/} folder above a file (read again each time: the user may edit them).
	 */
	public static Set<String> of(Resource r) {
		ResourceSet set = r.getResourceSet();
		if (set != null) {
			for (var a : set.eAdapters()) {
				if (a instanceof KnownQueries k) {
					return k.names;
				}
			}
		}
		Set<String> out = new TreeSet<>(defaults());
		URI uri = r.getURI();
		if (uri != null && uri.isFile()) {
			for (Path dir = Path.of(uri.toFileString()).toAbsolutePath().getParent(); dir != null; dir = dir
					.getParent()) {
				if (Files.isDirectory(dir.resolve("queries"))) {
					out.addAll(inFolder(dir.resolve("queries")));
					break;
				}
			}
		}
		return Collections.unmodifiableSet(out);
	}

	/** The names of the default queries, the ones the monitor always loads (read once: they are in the jar). */
	public static Set<String> defaults() {
		return Defaults.NAMES;
	}

	private static final class Defaults {
		static final Set<String> NAMES = Collections.unmodifiableSet(read());

		private static Set<String> read() {
			URL url = KnownQueries.class.getResource(DEFAULTS);
			if (url == null) { // the build copies them; without them every query would be unknown
				throw new IllegalStateException("packaged default queries missing: " + DEFAULTS);
			}
			try {
				java.net.URI uri = url.toURI();
				if (!"jar".equals(uri.getScheme())) {
					return inFolder(Path.of(uri));
				}
				FileSystem fs;
				try { // the monitor's jar holds this class too and may have opened it already
					fs = FileSystems.newFileSystem(uri, Map.of());
				} catch (FileSystemAlreadyExistsException e) {
					fs = FileSystems.getFileSystem(uri);
				}
				return inFolder(fs.getPath(DEFAULTS));
			} catch (URISyntaxException e) {
				throw new IllegalStateException(e);
			} catch (IOException e) {
				throw new UncheckedIOException(e);
			}
		}
	}

	/** The names of the queries declared in DRL text. */
	public static Set<String> inDrl(String drl) {
		Set<String> out = new TreeSet<>();
		Matcher m = QUERY.matcher(drl);
		while (m.find()) {
			out.add(m.group(1));
		}
		return out;
	}

	public static Set<String> inFolder(Path dir) {
		Set<String> out = new TreeSet<>();
		try (Stream<Path> files = Files.list(dir)) {
			for (Path p : files.filter(f -> f.toString().endsWith(".drl")).toList()) {
				out.addAll(inDrl(Files.readString(p)));
			}
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
		return out;
	}
}
