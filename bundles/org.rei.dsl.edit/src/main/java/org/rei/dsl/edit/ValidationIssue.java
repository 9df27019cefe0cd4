/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.util.List;

/**
 * A validator's finding, placed both in the text and on the diagram.
 *
 * @param severity "error", "warning" or "info"
 * @param line 1-based
 * @param column 1-based
 * @param code the issue code ({@code org.rei.dsl.floorOccupied}, ...), null for syntax errors
 * @param element the name of the element it is on (a goal's floor for a goal), null when it has none
 * @param kind what the element is: testcase, room, floor, wall, object, dynamic, human, robot, mission, goal,
 *            monitor
 * @param index a goal's place in the mission (from 0), else null
 * @param related the names of other elements the message is about, so that a diagram can show it on them too:
 *            for a floor taken twice ({@code org.rei.dsl.floorOccupied}, reported on the later object) the other
 *            objects and the robot that start on that floor; empty for the others
 */
public record ValidationIssue(String severity, String message, int line, int column, int offset, int length,
		String code, String element, String kind, Integer index, List<String> related) {

	public ValidationIssue {
		related = related == null ? List.of() : List.copyOf(related);
	}

	public boolean isError() {
		return "error".equals(severity);
	}
}
