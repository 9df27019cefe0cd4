/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.List;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.xtext.validation.Check;
import org.rei.context.ContextPackage.Literals;
import org.rei.context.Fault;
import org.rei.context.FaultKind;
import org.rei.context.GainPoint;

/**
 * A scheduled fault (docs/faults.md): its times in order, its pulse train inside its period, and only the
 * parameters of its kind, those a kind needs given, each in its range - the checks the simulator's reader makes
 * (rei.sim.faults.spec), here on the words that are wrong.
 */
public class FaultValidator extends ReiCheckBase {

	@Check
	public void checkTiming(Fault f) {
		if (f.isSetStart() && f.getStart() < 0) {
			error("'from' is a time: expected 0 s or later", f, Literals.FAULT__START, ReiIssueCodes.NEGATIVE_TIME);
		}
		if (f.isSetEnd() && !(f.getEnd() > (f.isSetStart() ? f.getStart() : 0))) {
			error("'to' must be after 'from' (" + (f.isSetStart() ? f.getStart() : 0) + " s)", f, Literals.FAULT__END,
					ReiIssueCodes.FAULT_TIME_ORDER);
		}
		if (f.isSetPeriod()) {
			if (!(f.getPeriod() > 0)) {
				error("The period of a pulse train must be positive, in seconds", f, Literals.FAULT__PERIOD,
						ReiIssueCodes.NON_POSITIVE);
			} else if (f.isSetPulse() && !(f.getPulse() > 0 && f.getPulse() <= f.getPeriod())) {
				error("The pulse must be longer than 0 s and at most the period (" + f.getPeriod() + " s)", f,
						Literals.FAULT__PULSE, ReiIssueCodes.OUT_OF_RANGE);
			}
			if (f.isSetDuty() && !(f.getDuty() > 0 && f.getDuty() <= 100)) {
				error("The duty is a share of the period: expected more than 0 % and at most 100 %", f,
						Literals.FAULT__DUTY, ReiIssueCodes.OUT_OF_RANGE);
			}
		}
	}

	@Check
	public void checkParameters(Fault f) {
		FaultKind kind = f.getKind();
		List<EAttribute> own = switch (kind) {
		case IMPULSE -> List.of(Literals.FAULT__RATE, Literals.FAULT__WIDTH);
		case NOISE -> List.of(Literals.FAULT__SIGMA);
		case OCCLUSION -> List.of(Literals.FAULT__ANGLE_FROM, Literals.FAULT__RANGE);
		default -> List.of();
		};
		for (EAttribute a : List.of(Literals.FAULT__RATE, Literals.FAULT__WIDTH, Literals.FAULT__SIGMA,
				Literals.FAULT__ANGLE_FROM, Literals.FAULT__RANGE)) {
			if (f.eIsSet(a) && !own.contains(a)) {
				error("A laser " + kind.getLiteral() + " fault has no '" + keyword(a) + "'" + keysOf(kind), f, a,
						ReiIssueCodes.FAULT_PARAMETER);
			}
		}
		if (!f.getOwnedGain().isEmpty() && kind != FaultKind.IMPULSE) {
			error("A laser " + kind.getLiteral() + " fault has no 'gain'" + keysOf(kind), f, Literals.FAULT__OWNED_GAIN,
					0, ReiIssueCodes.FAULT_PARAMETER);
		}
		if (kind == FaultKind.NOISE && !f.isSetSigma()) {
			error("A laser noise fault needs 'sigma' (metres)", f, Literals.FAULT__KIND, ReiIssueCodes.FAULT_PARAMETER);
		}
		if (kind == FaultKind.OCCLUSION && (!f.isSetAngleFrom() || !f.isSetRange())) {
			error("A laser occlusion fault needs 'angles FROM to TO' (degrees) and 'range' (metres)", f,
					Literals.FAULT__KIND, ReiIssueCodes.FAULT_PARAMETER);
		}
		if (f.isSetRate() && !(f.getRate() >= 0 && f.getRate() <= 1)) {
			error("The rate is impulses per beam per scan: expected 0 to 1", f, Literals.FAULT__RATE,
					ReiIssueCodes.OUT_OF_RANGE);
		}
		if (f.isSetWidth() && f.getWidth() < 1) {
			error("The width counts beams: expected 1 or more", f, Literals.FAULT__WIDTH, ReiIssueCodes.NON_POSITIVE);
		}
		if (f.isSetSigma() && !(f.getSigma() > 0)) {
			error("sigma must be positive, in metres", f, Literals.FAULT__SIGMA, ReiIssueCodes.NON_POSITIVE);
		}
		if (f.isSetRange() && f.getRange() < 0) {
			error("The range is a distance: expected 0 m or more", f, Literals.FAULT__RANGE, ReiIssueCodes.OUT_OF_RANGE);
		}
	}

	@Check
	public void checkGain(Fault f) {
		List<GainPoint> points = f.getOwnedGain();
		Double last = null;
		for (GainPoint p : points) {
			if (p.getValue() < 0) {
				error("A gain is a share of the lidar's maximum range: expected 0 or more", p, Literals.GAIN_POINT__VALUE,
						ReiIssueCodes.OUT_OF_RANGE);
			}
			if (points.size() > 1 && !p.isSetAt()) {
				error("A gain that changes needs 'at' on every value (e.g. gain 0.2 at 0s, 0.8 at 30s)", p,
						Literals.GAIN_POINT__VALUE, ReiIssueCodes.FAULT_PARAMETER);
			} else if (p.isSetAt()) {
				if (p.getAt() < 0) {
					error("'at' is a time: expected 0 s or later", p, Literals.GAIN_POINT__AT, ReiIssueCodes.NEGATIVE_TIME);
				} else if (last != null && !(p.getAt() > last)) {
					error("The gain's times must increase: " + p.getAt() + " s after " + last + " s", p,
							Literals.GAIN_POINT__AT, ReiIssueCodes.FAULT_TIME_ORDER);
				}
				last = p.getAt();
			}
		}
	}

	private static String keyword(EAttribute a) {
		return a == Literals.FAULT__ANGLE_FROM ? "angles" : a.getName();
	}

	private static String keysOf(FaultKind kind) {
		return switch (kind) {
		case IMPULSE -> " (its parameters: rate, width, gain)";
		case NOISE -> " (its parameter: sigma)";
		case OCCLUSION -> " (its parameters: angles, range)";
		default -> " (it has no parameters besides its times)";
		};
	}
}
