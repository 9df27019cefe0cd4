/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.List;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.validation.Check;
import org.rei.catalogue.Drive;
import org.rei.catalogue.RobotType;
import org.rei.context.ContextPackage.Literals;
import org.rei.context.Fault;
import org.rei.context.FaultKind;
import org.rei.context.FaultSensor;
import org.rei.context.GainPoint;
import org.rei.context.Robot;
import org.rei.context.TestCase;

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

	/** The parameters each kind has, in the order they are named in messages. */
	private static List<EStructuralFeature> own(FaultKind kind) {
		return switch (kind) {
		case IMPULSE -> List.of(Literals.FAULT__RATE, Literals.FAULT__WIDTH, Literals.FAULT__OWNED_GAIN);
		case NOISE -> List.of(Literals.FAULT__SIGMA);
		case OCCLUSION -> List.of(Literals.FAULT__ANGLE_FROM, Literals.FAULT__RANGE);
		case DRIFT -> List.of(Literals.FAULT__SCALE, Literals.FAULT__BIAS);
		case JUMP, KIDNAP -> List.of(Literals.FAULT__DX, Literals.FAULT__DY, Literals.FAULT__DYAW);
		case SLIP -> List.of(Literals.FAULT__FRACTION);
		case STUCK -> List.of(Literals.FAULT__WHEEL);
		case LATENCY -> List.of(Literals.FAULT__DELAY);
		case LOSS -> List.of(Literals.FAULT__PROBABILITY);
		default -> List.of();
		};
	}

	/** The sensor each kind belongs to (contract/vocabulary.json faults.kinds). */
	private static FaultSensor sensorOf(FaultKind kind) {
		return switch (kind) {
		case DRIFT, JUMP -> FaultSensor.ODOMETRY;
		case SLIP, STUCK -> FaultSensor.DRIVE;
		case LATENCY, LOSS -> FaultSensor.COMMANDS;
		case KIDNAP -> FaultSensor.POSE;
		default -> FaultSensor.LASER;
		};
	}

	private static final List<EAttribute> PARAMETERS = List.of(Literals.FAULT__RATE, Literals.FAULT__WIDTH,
			Literals.FAULT__SIGMA, Literals.FAULT__ANGLE_FROM, Literals.FAULT__RANGE, Literals.FAULT__DELAY,
			Literals.FAULT__PROBABILITY, Literals.FAULT__FRACTION, Literals.FAULT__WHEEL, Literals.FAULT__SCALE,
			Literals.FAULT__BIAS, Literals.FAULT__DX, Literals.FAULT__DY, Literals.FAULT__DYAW);

	@Check
	public void checkParameters(Fault f) {
		FaultKind kind = f.getKind();
		String name = f.getSensor().getLiteral() + " " + kind.getLiteral();
		if (sensorOf(kind) != f.getSensor()) {
			error("'" + kind.getLiteral() + "' is a fault of the " + sensorOf(kind).getLiteral() + ", not of the "
					+ f.getSensor().getLiteral(), f, Literals.FAULT__KIND, ReiIssueCodes.FAULT_PARAMETER);
			return;
		}
		List<EStructuralFeature> own = own(kind);
		for (EAttribute a : PARAMETERS) {
			if (f.eIsSet(a) && !own.contains(a)) {
				error(article(name) + " fault has no '" + keyword(a) + "'" + keysOf(own), f, a,
						ReiIssueCodes.FAULT_PARAMETER);
			}
		}
		if (!f.getOwnedGain().isEmpty() && kind != FaultKind.IMPULSE) {
			error(article(name) + " fault has no 'gain'" + keysOf(own), f, Literals.FAULT__OWNED_GAIN, 0,
					ReiIssueCodes.FAULT_PARAMETER);
		}
		String needs = switch (kind) {
		case NOISE -> f.isSetSigma() ? null : "'sigma' (metres)";
		case OCCLUSION -> f.isSetAngleFrom() && f.isSetRange() ? null
				: "'angles FROM to TO' (degrees) and 'range' (metres)";
		case LATENCY -> f.isSetDelay() ? null : "'delay' (seconds)";
		case LOSS -> f.isSetProbability() ? null : "'probability'";
		case SLIP -> f.isSetFraction() ? null : "'fraction'";
		case STUCK -> f.isSetWheel() ? null : "'wheel' (left or right)";
		// a scale of 1 and a bias of 0 change nothing, and the simulator refuses such a drift
		case DRIFT -> (f.isSetScale() && f.getScale() != 1) || (f.isSetBias() && f.getBias() != 0) ? null
				: "'scale' other than 1 or 'bias' other than 0";
		case JUMP, KIDNAP -> (f.isSetDx() && f.getDx() != 0) || (f.isSetDy() && f.getDy() != 0)
				|| (f.isSetDyaw() && f.getDyaw() != 0) ? null : "an offset: 'dx', 'dy' or 'dyaw' other than 0";
		default -> null;
		};
		if (needs != null) {
			error(article(name) + " fault needs " + needs, f, Literals.FAULT__KIND, ReiIssueCodes.FAULT_PARAMETER);
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
		if (f.isSetDelay() && !(f.getDelay() > 0)) {
			error("The delay must be positive, in seconds (a whole number of control periods)", f,
					Literals.FAULT__DELAY, ReiIssueCodes.NON_POSITIVE);
		}
		if (f.isSetProbability() && !(f.getProbability() > 0 && f.getProbability() <= 1)) {
			error("The probability that a command is lost: expected more than 0 and at most 1", f,
					Literals.FAULT__PROBABILITY, ReiIssueCodes.OUT_OF_RANGE);
		}
		if (f.isSetFraction() && !(f.getFraction() > 0 && f.getFraction() <= 1)) {
			error("The fraction of the commanded motion the robot makes: expected more than 0 and at most 1", f,
					Literals.FAULT__FRACTION, ReiIssueCodes.OUT_OF_RANGE);
		}
		if (f.isSetScale() && !(f.getScale() > 0)) {
			error("The odometry's scale must be positive", f, Literals.FAULT__SCALE, ReiIssueCodes.NON_POSITIVE);
		}
	}

	/**
	 * A stuck wheel is one of a differential drive's two: the simulator's holonomic drive has no left or right
	 * wheel to stop (docs/robots.md#drives), so the fault would mean nothing there.
	 */
	@Check
	public void checkDriveOfRobot(Fault f) {
		if (f.getKind() != FaultKind.STUCK || !(f.eContainer() instanceof TestCase testCase)
				|| testCase.getOwnedEnvironment() == null) {
			return;
		}
		Robot robot = testCase.getOwnedEnvironment().getOwnedRobot();
		if (robot != null && robot.getType() instanceof RobotType type && type.getDrive() == Drive.HOLONOMIC) {
			error("A stuck wheel is a fault of a differential drive: the robot " + robot.getName() + " ("
					+ type.getName() + ") is holonomic", f, Literals.FAULT__KIND, ReiIssueCodes.FAULT_PARAMETER);
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

	private static String keyword(EStructuralFeature a) {
		return a == Literals.FAULT__ANGLE_FROM ? "angles" : a == Literals.FAULT__OWNED_GAIN ? "gain" : a.getName();
	}

	private static String article(String name) {
		return ("aeiou".indexOf(name.charAt(0)) >= 0 ? "An " : "A ") + name;
	}

	private static String keysOf(List<EStructuralFeature> own) {
		if (own.isEmpty()) {
			return " (it has no parameters besides its times)";
		}
		return (own.size() == 1 ? " (its parameter: " : " (its parameters: ")
				+ String.join(", ", own.stream().map(FaultValidator::keyword).toList()) + ")";
	}
}
