/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.util.List;

/**
 * One entry of animation.json's {@code people} (docs/artifacts.md): a human on a route as written, or one of the
 * people a crowd or a group is expanded into. The templates read it as {@code p.name()}, {@code p.route()}, ...
 *
 * @param behaviour the grammar's word: {@code avoids}, {@code ignores}, {@code curious}, {@code scared},
 *                  {@code blocks}
 * @param speedTo   the fastest of a speed range, {@code null} for one speed
 * @param group     the group the person walks with, {@code null} for anyone else
 */
public record Person(String name, String behaviour, double speed, Double speedTo, double start, boolean loop,
		String group, List<Stop> route) {

	/**
	 * A place the person walks to (the first: where it stands at the start): a floor's centre, or a point of it.
	 *
	 * @param queueSeconds a crowd's queue: the seconds between two people passing here, {@code null} elsewhere
	 */
	public record Stop(String floor, double x, double y, double waitSeconds, Double queueSeconds) {

		public Stop(String floor, double x, double y, double waitSeconds) {
			this(floor, x, y, waitSeconds, null);
		}
	}
}
