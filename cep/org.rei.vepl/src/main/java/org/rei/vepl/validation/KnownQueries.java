/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.validation;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
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
 * the queries it will run to the resource set; an editor without that finds the repository's {@code queries/}
 * folder above the file. With neither, query names are not checked.
 */
public final class KnownQueries extends AdapterImpl {

	private static final Pattern QUERY = Pattern.compile("(?m)^\\s*query\\s+([A-Za-z_$][\\w$]*)");

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

	/** The known names for a resource, or null when they cannot be known. */
	public static Set<String> of(Resource r) {
		ResourceSet set = r.getResourceSet();
		if (set != null) {
			for (var a : set.eAdapters()) {
				if (a instanceof KnownQueries k) {
					return k.names;
				}
			}
		}
		URI uri = r.getURI();
		if (uri != null && uri.isFile()) {
			for (Path dir = Path.of(uri.toFileString()).toAbsolutePath().getParent(); dir != null; dir = dir
					.getParent()) {
				if (Files.isDirectory(dir.resolve("queries"))) {
					return inFolder(dir.resolve("queries"));
				}
			}
		}
		return null;
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
