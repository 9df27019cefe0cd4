/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

/** Codes of the issues the validators report; tests and quick fixes key on these, not on message text. */
public interface ReiIssueCodes {
	String PREFIX = "org.rei.dsl.";

	String DUPLICATE_NAME = PREFIX + "duplicateName";
	String MISSING_ROBOT = PREFIX + "missingRobot";
	String MULTIPLE_ROBOTS = PREFIX + "multipleRobots";
	String BLOCKS_WITH_LAYOUT = PREFIX + "blocksWithLayout";
	String EMPTY_LAYOUT = PREFIX + "emptyLayout";
	String ROOM_TOO_LARGE = PREFIX + "roomTooLarge";
	String MAP_UNREADABLE = PREFIX + "mapUnreadable";
	String NON_POSITIVE = PREFIX + "nonPositive";
	String TYPE_CATEGORY = PREFIX + "typeCategory";
	String FLOOR_OCCUPIED = PREFIX + "floorOccupied";
	String TRAJECTORY_TOO_SHORT = PREFIX + "trajectoryTooShort";
	String TRAJECTORY_TIME_ORDER = PREFIX + "trajectoryTimeOrder";
	String NEGATIVE_TIME = PREFIX + "negativeTime";
	String STOP_OCCUPIED = PREFIX + "stopOccupied";
	String STOP_UNREACHABLE = PREFIX + "stopUnreachable";
	String TOO_FEW_PEOPLE = PREFIX + "tooFewPeople";
	String AREA_TOO_SMALL = PREFIX + "areaTooSmall";
	String AREA_UNREACHABLE = PREFIX + "areaUnreachable";
	String MISSING_MISSION = PREFIX + "missingMission";
	String TOO_FEW_GOALS = PREFIX + "tooFewGoals";
	String GOAL_UNREACHABLE = PREFIX + "goalUnreachable";
	String GOAL_OCCUPIED = PREFIX + "goalOccupied";
	String THRESHOLD_ORDER = PREFIX + "thresholdOrder";
	String CATALOGUE_IMPORT = PREFIX + "catalogueImport";
	String CATALOGUE_INVALID = PREFIX + "catalogueInvalid";
	String ROBOT_DESCRIPTION = PREFIX + "robotDescription";
	String CYLINDER_SIZE = PREFIX + "cylinderSize";
	String POLYGON = PREFIX + "polygon";
	String COLOUR = PREFIX + "colour";
	String OUT_OF_RANGE = PREFIX + "outOfRange";
	String FAULT_TIME_ORDER = PREFIX + "faultTimeOrder";
	String FAULT_PARAMETER = PREFIX + "faultParameter";
}
