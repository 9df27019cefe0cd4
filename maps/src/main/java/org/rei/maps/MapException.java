/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import java.nio.file.Path;

/**
 * A map that cannot be read: {@code file:line:column: field: what is wrong} (line and column from 1, in the YAML
 * file), as the Python side's {@code rei.maps.MapError} says it. The field is a map_server field ({@code image},
 * {@code origin}, ...) or {@code file} for the YAML file as a whole.
 */
public final class MapException extends Exception {

	private static final long serialVersionUID = 1L;

	private final transient Path file;
	private final int line;
	private final int column;
	private final String field;
	private final String detail;
	private final transient Path image;

	public MapException(Path file, int line, int column, String field, String detail) {
		this(file, line, column, field, detail, null);
	}

	/** A problem of the image file {@code image} (reported at the YAML's {@code image} field). */
	public MapException(Path file, int line, int column, String field, String detail, Path image) {
		super(file + ":" + line + ":" + column + ": " + field + ": " + detail);
		this.image = image;
		this.file = file;
		this.line = line;
		this.column = column;
		this.field = field;
		this.detail = detail;
	}

	/** The YAML file. */
	public Path file() {
		return file;
	}

	/** Line in the YAML file, from 1. */
	public int line() {
		return line;
	}

	/** Column in the YAML file, from 1. */
	public int column() {
		return column;
	}

	/** The map_server field concerned, or {@code file}. */
	public String field() {
		return field;
	}

	/** The image file when it is the problem, else {@code null}. */
	public Path image() {
		return image;
	}

	/** What is wrong, without the position. */
	public String detail() {
		return detail;
	}
}
