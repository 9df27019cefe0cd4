/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.util.List;

/**
 * What an edit (or an undo) did: the new text, the edits that turn the previous text into it (ascending, not
 * overlapping, offsets into the previous text), and the validators' findings on the new text.
 */
public record EditResult(String text, List<TextEdit> edits, List<ValidationIssue> issues) {

	public boolean hasErrors() {
		return issues.stream().anyMatch(ValidationIssue::isError);
	}
}
