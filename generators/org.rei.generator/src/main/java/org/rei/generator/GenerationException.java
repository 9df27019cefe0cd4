/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.util.List;

import org.rei.context.layout.LayoutProblem;

/** The test case cannot be turned into artifacts; {@link #problems()} says why when the room cannot be laid out. */
public class GenerationException extends Exception {

	private static final long serialVersionUID = 1L;

	private final transient List<LayoutProblem> problems;

	/** A failure that is not about the layout (missing floor, bad trajectory, template error, I/O). */
	public GenerationException(String message, Throwable cause) {
		super(message, cause);
		this.problems = List.of();
	}

	/** A failure that is not about the layout. */
	public GenerationException(String message) {
		this(message, (Throwable) null);
	}

	/** The room cannot be laid out. */
	public GenerationException(String message, List<LayoutProblem> problems) {
		super(message);
		this.problems = List.copyOf(problems);
	}

	/** Layout problems, empty when the failure has another cause. */
	public List<LayoutProblem> problems() {
		return problems;
	}
}
