/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/** Applying, inverting and tidying lists of {@link TextEdit}s (ascending, not overlapping). */
final class TextEdits {

	private TextEdits() {
	}

	static List<TextEdit> sorted(List<TextEdit> edits) {
		List<TextEdit> result = new ArrayList<>(edits);
		result.sort(Comparator.comparingInt(TextEdit::offset).thenComparingInt(TextEdit::length));
		for (int i = 1; i < result.size(); i++) {
			if (result.get(i).offset() < result.get(i - 1).end()) {
				throw new IllegalStateException("overlapping edits " + result.get(i - 1) + " and " + result.get(i));
			}
		}
		return result;
	}

	static String apply(String text, List<TextEdit> edits) {
		StringBuilder out = new StringBuilder(text.length() + 64);
		int at = 0;
		for (TextEdit edit : edits) {
			out.append(text, at, edit.offset()).append(edit.replacement());
			at = edit.end();
		}
		return out.append(text, at, text.length()).toString();
	}

	/** One edit from the first to the last character that differ (nothing when the texts are equal). */
	static List<TextEdit> between(String before, String after) {
		int prefix = 0;
		int limit = Math.min(before.length(), after.length());
		while (prefix < limit && before.charAt(prefix) == after.charAt(prefix)) {
			prefix++;
		}
		int suffix = 0;
		while (suffix < limit - prefix
				&& before.charAt(before.length() - 1 - suffix) == after.charAt(after.length() - 1 - suffix)) {
			suffix++;
		}
		if (prefix == before.length() && prefix == after.length()) {
			return List.of();
		}
		return List.of(new TextEdit(prefix, before.length() - prefix - suffix,
				after.substring(prefix, after.length() - suffix)));
	}

	/** The edits that turn {@code apply(text, edits)} back into {@code text}. */
	static List<TextEdit> inverse(String text, List<TextEdit> edits) {
		List<TextEdit> result = new ArrayList<>(edits.size());
		int shift = 0;
		for (TextEdit edit : edits) {
			result.add(new TextEdit(edit.offset() + shift, edit.replacement().length(),
					text.substring(edit.offset(), edit.end())));
			shift += edit.replacement().length() - edit.length();
		}
		return result;
	}

	/**
	 * Xtext keeps the blanks on both sides of what it deletes: "on F_0_0 yaw 90" loses "yaw 90" but keeps the blank
	 * before it at the end of the line, "floor B left A top W1" becomes "floor B  top W1". A deletion that is
	 * followed by a line end takes the blanks before it along, one between blanks takes those after it. Blanks
	 * next to an edit are always hidden whitespace: comments and strings end in a line break, a quote or slash.
	 */
	static List<TextEdit> tidy(String text, List<TextEdit> edits) {
		List<TextEdit> result = new ArrayList<>(edits.size());
		int previousEnd = 0;
		for (int i = 0; i < edits.size(); i++) {
			TextEdit edit = edits.get(i);
			int nextStart = i + 1 < edits.size() ? edits.get(i + 1).offset() : text.length();
			if (!edit.replacement().isEmpty()) {
				result.add(edit);
				previousEnd = edit.end();
				continue;
			}
			int start = edit.offset();
			while (start > previousEnd && isBlank(text.charAt(start - 1))) {
				start--;
			}
			boolean afterToken = start > 0 && start < edit.offset() && !isLineBreak(text.charAt(start - 1));
			int end = edit.end();
			if (afterToken && (end == text.length() || isLineBreak(text.charAt(end)))) {
				result.add(new TextEdit(start, end - start, ""));
			} else if (afterToken && isBlank(text.charAt(end))) {
				while (end < nextStart && isBlank(text.charAt(end))) {
					end++;
				}
				result.add(new TextEdit(edit.offset(), end - edit.offset(), ""));
			} else {
				result.add(edit);
			}
			previousEnd = result.get(result.size() - 1).end();
		}
		return result;
	}

	private static boolean isBlank(char c) {
		return c == ' ' || c == '\t';
	}

	private static boolean isLineBreak(char c) {
		return c == '\n' || c == '\r';
	}
}
