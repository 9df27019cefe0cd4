/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import org.eclipse.xtext.validation.Check;
import org.rei.context.ContextPackage;
import org.rei.context.MonitorSpec;

/** Thresholds of the geometric states (thesis 5.1.6.2): 0 < eps_collision < eps_close. */
public class MonitorValidator extends ReiCheckBase {

	@Check
	public void checkThresholds(MonitorSpec spec) {
		if (!(spec.getEpsCollision() > 0)) {
			error("The collision threshold must be positive, in metres", spec,
					ContextPackage.Literals.MONITOR_SPEC__EPS_COLLISION, ReiIssueCodes.NON_POSITIVE);
		} else if (!(spec.getEpsClose() > spec.getEpsCollision())) {
			error("The close threshold must be larger than the collision threshold (" + spec.getEpsCollision() + " m)",
					spec, ContextPackage.Literals.MONITOR_SPEC__EPS_CLOSE, ReiIssueCodes.THRESHOLD_ORDER);
		}
		if (spec.getMaxHumanCollisions() < 1) {
			error("maxHumanCollisions is N_COLLISION of thesis Table 4 (collisions must stay below it): "
					+ "expected 1 or more", spec, ContextPackage.Literals.MONITOR_SPEC__MAX_HUMAN_COLLISIONS,
					ReiIssueCodes.NON_POSITIVE);
		}
	}
}
