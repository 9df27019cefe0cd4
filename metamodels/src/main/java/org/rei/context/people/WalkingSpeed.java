/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.people;

import org.rei.catalogue.ObjectType;
import org.rei.context.Crowd;
import org.rei.context.Route;

/**
 * How fast a person who sees the robot wants to walk, in m/s: one speed, or a range {@code speed..speedTo} the
 * simulation draws the person's speed from with the run's seed (animation.json's {@code speed} and
 * {@code speedTo}). The statement's own {@code speed} when it writes one; else its type's walking speed when the
 * type declares one; else {@link #DEFAULT}.
 *
 * @param speedTo the fastest of a range, {@code null} for one speed
 */
public record WalkingSpeed(double speed, Double speedTo) {

	/** The speed of a person whose statement and type say nothing, m/s. */
	public static final double DEFAULT = 1.2;

	/** A person on a route, or a group (its route), of a type ({@code null}: the default Human, who says none). */
	public static WalkingSpeed of(Route route, ObjectType type) {
		if (route.isSetSpeed()) {
			return new WalkingSpeed(route.getSpeed(), route.isSetSpeedTo() ? route.getSpeedTo() : null);
		}
		return of(type);
	}

	/** The people of a crowd. */
	public static WalkingSpeed of(Crowd crowd) {
		if (crowd.isSetSpeed()) {
			return new WalkingSpeed(crowd.getSpeed(), crowd.isSetSpeedTo() ? crowd.getSpeedTo() : null);
		}
		return of(crowd.getType());
	}

	/** What a type declares, else {@link #DEFAULT}. */
	public static WalkingSpeed of(ObjectType type) {
		if (type != null && !type.eIsProxy() && type.isSetWalkingSpeed()) {
			return new WalkingSpeed(type.getWalkingSpeed(), type.isSetWalkingSpeedTo() ? type.getWalkingSpeedTo() : null);
		}
		return new WalkingSpeed(DEFAULT, null);
	}

	/** Whether the speed is drawn from a range. */
	public boolean isRange() {
		return speedTo != null;
	}
}
