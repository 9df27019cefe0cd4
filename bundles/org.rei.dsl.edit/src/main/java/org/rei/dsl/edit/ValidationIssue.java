/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

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
 */
public record ValidationIssue(String severity, String message, int line, int column, int offset, int length,
		String code, String element, String kind, Integer index) {

	public boolean isError() {
		return "error".equals(severity);
	}
}
