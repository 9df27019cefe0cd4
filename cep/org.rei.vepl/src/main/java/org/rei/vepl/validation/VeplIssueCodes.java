/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.validation;

/** Codes of the issues the validator reports; tests and quick fixes key on these, not on message text. */
public interface VeplIssueCodes {
	String PREFIX = "org.rei.vepl.";

	String DUPLICATE_NAME = PREFIX + "duplicateName";
	String UNKNOWN_QUERY = PREFIX + "unknownQuery";
	String UNKNOWN_MISSION_EVENT = PREFIX + "unknownMissionEvent";
	String CONTRADICTORY_WINDOW = PREFIX + "contradictoryWindow";
	String NEGATION_OPERAND = PREFIX + "negationOperand";
	String NEGATION_PLACE = PREFIX + "negationPlace";
	String UNBOUNDED_NEGATION = PREFIX + "unboundedNegation";
	String EMPTY_MATCH = PREFIX + "emptyMatch";
	String CYCLIC_EVENT = PREFIX + "cyclicEvent";
	String SECOND_RULE = PREFIX + "secondRule";
	String EMPTY_FILE = PREFIX + "emptyFile";
	String IGNORED_HEADER = PREFIX + "ignoredHeader";
	String ACTION_BLOCK = PREFIX + "actionBlock";
	String TOO_DEEP = PREFIX + "tooDeep";
	/** The parser or a check failed on the file (a bug): the file gets this error instead of a crash. */
	String UNREADABLE = PREFIX + "unreadable";
	String TRANSITION_STEP = PREFIX + "transitionStep";
}
