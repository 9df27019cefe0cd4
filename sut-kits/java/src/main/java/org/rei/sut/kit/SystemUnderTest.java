/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/**
 * A system under test written as callbacks. {@link SutClient} calls them one at a time, on the thread that called
 * {@link SutClient#run}, in the order the simulation sent the messages: {@code onStart} first, then goals,
 * cancellations and ticks, {@code onEnd} last. A callback that throws stops the SUT (exit code 1).
 */
public interface SystemUnderTest {

	/** The run starts: start pose, robot limits, laser, control rate and (with {@code --sut-map}) the map. */
	default void onStart(Session session) throws Exception {
	}

	/**
	 * A new goal, replacing the previous one. It is {@link GoalStatus#ACTIVE} unless this callback reports
	 * otherwise; the state is published when the callback returns.
	 */
	default void onGoal(Goal goal) throws Exception {
	}

	/**
	 * The mission withdrew {@code goal} (e.g. its timeout). It is {@link GoalStatus#CANCELLED} ("cancelled by the
	 * client") unless this callback reports otherwise.
	 */
	default void onCancel(Goal goal) throws Exception {
	}

	/**
	 * One control period: return the velocity command for it (never null). Goal reports made here are published
	 * before the command, and only if the goal's state or text changed.
	 */
	Command onTick(Tick tick) throws Exception;

	/** The run is over ({@code reason} says why); {@link SutClient#run} returns after this. */
	default void onEnd(String reason) throws Exception {
	}
}
