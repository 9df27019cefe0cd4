/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

/**
 * The footprint distance between the robot and one obstacle near it (inside the pre-filter radius), and whether
 * the simulator reports them touching. One fact per nearby obstacle, updated in place while it stays nearby.
 */
public final class Proximity {

	private final String robot;
	private final String object;
	private final String category;
	private double distance;
	private boolean contact;

	public Proximity(String robot, String object, String category, double distance, boolean contact) {
		this.robot = robot;
		this.object = object;
		this.category = category;
		this.distance = distance;
		this.contact = contact;
	}

	public String getRobot() {
		return robot;
	}

	public String getObject() {
		return object;
	}

	public String getCategory() {
		return category;
	}

	public double getDistance() {
		return distance;
	}

	public boolean isContact() {
		return contact;
	}

	/** Sets the new values; true when they changed (only then is the fact updated in the session). */
	boolean set(double d, boolean touching) {
		boolean changed = d != distance || touching != contact;
		distance = d;
		contact = touching;
		return changed;
	}

	@Override
	public String toString() {
		return "Proximity(" + robot + ", " + object + ", " + distance + (contact ? ", contact" : "") + ")";
	}
}
