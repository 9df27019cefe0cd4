/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

/**
 * A navigation goal in the world frame and the handle to report its state, like an action server's goal handle.
 * A report takes effect when the callback making it returns: the kit then publishes the goal's state if it differs
 * from the last one published for this goal (so reporting the same state every tick costs nothing). Reports on a
 * goal that a newer one replaced are not published (the simulation would ignore them). Call these methods from the
 * callbacks only.
 */
public final class Goal {

	/** The protocol's limit for a status text. */
	public static final int MAX_TEXT = 1000;

	private final int id;
	private final double t;
	private final Pose pose;
	private final double tolerance;
	private GoalStatus status = GoalStatus.ACTIVE;
	private String text;

	public Goal(int id, double t, Pose pose, double tolerance) {
		this.id = id;
		this.t = t;
		this.pose = pose;
		this.tolerance = tolerance;
	}

	/** The task's index in the mission (0, 1, ...). */
	public int id() {
		return id;
	}

	/** When the goal was sent (simulation clock, s). */
	public double t() {
		return t;
	}

	/** Where to go, in the world frame. */
	public Pose pose() {
		return pose;
	}

	/** How close (m) the robot's true position must be for the mission to accept SUCCEEDED. */
	public double tolerance() {
		return tolerance;
	}

	public GoalStatus status() {
		return status;
	}

	/** The text of the last report, or null. */
	public String text() {
		return text;
	}

	/** Still working on it: {@link GoalStatus#ACTIVE}. */
	public boolean isActive() {
		return status == GoalStatus.ACTIVE;
	}

	/** Working on it; a new {@code text} is feedback (published once per change). */
	public void active(String text) {
		report(GoalStatus.ACTIVE, text);
	}

	public void succeeded(String text) {
		report(GoalStatus.SUCCEEDED, text);
	}

	/** Given up; {@code text} becomes the task's failure reason. */
	public void aborted(String text) {
		report(GoalStatus.ABORTED, text);
	}

	public void cancelled(String text) {
		report(GoalStatus.CANCELLED, text);
	}

	/** Sets the state; a text longer than {@link #MAX_TEXT} characters is cut there, null means none. */
	public void report(GoalStatus newStatus, String newText) {
		if (newStatus == null) {
			throw new IllegalArgumentException("status is null");
		}
		status = newStatus;
		text = newText == null || newText.length() <= MAX_TEXT ? newText : newText.substring(0, MAX_TEXT);
	}

	@Override
	public String toString() {
		return "Goal[id=" + id + ", pose=" + pose + ", tolerance=" + tolerance + ", " + status
				+ (text != null ? " (" + text + ")" : "") + "]";
	}
}
