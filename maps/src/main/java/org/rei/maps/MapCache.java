/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Loaded maps (and their errors) by YAML path, kept while the YAML and its image keep their modification time and
 * size: the editor validates a room on every keystroke, and a map of 1.7 million cells must not be read each time.
 * The few most recently used maps are kept.
 */
public final class MapCache {

	private static final int KEPT = 4;

	private record Stamp(long modified, long size) {
		static Stamp of(Path file) {
			try {
				BasicFileAttributes a = Files.readAttributes(file, BasicFileAttributes.class);
				return new Stamp(a.lastModifiedTime().toMillis(), a.size());
			} catch (IOException e) {
				return new Stamp(-1, -1);
			}
		}
	}

	/** One outcome of reading a map: the map or its error, with the stamps it was read under. */
	private record Entry(Stamp yaml, Path image, Stamp imageStamp, OccupancyMap map, MapException error) {
		boolean current(Path yamlPath) {
			return yaml.equals(Stamp.of(yamlPath)) && (image == null || imageStamp.equals(Stamp.of(image)));
		}
	}

	private static final Map<Path, Entry> ENTRIES = new LinkedHashMap<>(8, 0.75f, true) {
		private static final long serialVersionUID = 1L;

		@Override
		protected boolean removeEldestEntry(Map.Entry<Path, Entry> eldest) {
			return size() > KEPT;
		}
	};

	private MapCache() {
	}

	/** The map of a YAML file, read once per version of the YAML and its image. */
	public static OccupancyMap get(Path yaml) throws MapException {
		Path key = yaml.toAbsolutePath().normalize();
		Entry entry;
		synchronized (ENTRIES) {
			entry = ENTRIES.get(key);
		}
		if (entry == null || !entry.current(key)) {
			entry = load(key);
			synchronized (ENTRIES) {
				ENTRIES.put(key, entry);
			}
		}
		if (entry.error() != null) {
			throw entry.error();
		}
		return entry.map();
	}

	private static Entry load(Path yaml) {
		// stamps first: a file changed while it is read is read again next time
		Stamp stamp = Stamp.of(yaml);
		try {
			OccupancyMap map = MapReader.read(yaml);
			return new Entry(stamp, map.image(), Stamp.of(map.image()), map, null);
		} catch (MapException e) {
			// the image is named by the YAML: when it was the problem, its change must be noticed too
			Path image = e.image();
			return new Entry(stamp, image, image == null ? null : Stamp.of(image), null, e);
		}
	}
}
