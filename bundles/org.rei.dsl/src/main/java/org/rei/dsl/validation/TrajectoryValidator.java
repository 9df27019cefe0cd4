/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.List;

import org.eclipse.xtext.validation.Check;
import org.rei.context.ContextPackage;
import org.rei.context.ControlPoint;
import org.rei.context.Trajectory;

/** Trajectories (thesis 4.2): at least two control floors, at non-negative, strictly increasing times. */
public class TrajectoryValidator extends ReiCheckBase {

	@Check
	public void checkAtLeastTwoPoints(Trajectory trajectory) {
		if (trajectory.getOwnedControlPoints().size() < 2) {
			error("A trajectory needs at least two control points, e.g. [F_0_0 @ 0s, F_3_0 @ 5s]", trajectory, null,
					ReiIssueCodes.TRAJECTORY_TOO_SHORT);
		}
	}

	@Check
	public void checkTimes(Trajectory trajectory) {
		List<ControlPoint> points = trajectory.getOwnedControlPoints();
		for (int i = 0; i < points.size(); i++) {
			ControlPoint point = points.get(i);
			if (i == 0 && point.getTime() < 0) {
				error("Times start at 0s or later", point, ContextPackage.Literals.CONTROL_POINT__TIME,
						ReiIssueCodes.NEGATIVE_TIME);
			}
			if (i > 0 && !(point.getTime() > points.get(i - 1).getTime())) {
				error("Times must increase strictly: expected a time after " + seconds(points.get(i - 1).getTime()),
						point, ContextPackage.Literals.CONTROL_POINT__TIME, ReiIssueCodes.TRAJECTORY_TIME_ORDER);
			}
		}
	}

	private static String seconds(double time) {
		return (time == Math.rint(time) ? Long.toString((long) time) : Double.toString(time)) + "s";
	}
}
