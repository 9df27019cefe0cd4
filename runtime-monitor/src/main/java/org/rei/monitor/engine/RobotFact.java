/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

/**
 * The robot as the queries see it: its name and the obstacle that matters most right now (a colliding one if any,
 * else the nearest), which robot-level queries report as the object of a transition.
 */
public final class RobotFact {

	private final String name;
	private String nearestObject = "";
	private double nearestDistance = Double.POSITIVE_INFINITY;

	public RobotFact(String name) {
		this.name = name;
	}

	public String getName() {
		return name;
	}

	public String getNearestObject() {
		return nearestObject;
	}

	public double getNearestDistance() {
		return nearestDistance;
	}

	boolean set(String object, double distance) {
		boolean changed = !object.equals(nearestObject) || distance != nearestDistance;
		nearestObject = object;
		nearestDistance = distance;
		return changed;
	}
}
