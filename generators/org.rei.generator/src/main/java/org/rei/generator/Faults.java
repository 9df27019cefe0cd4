/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.rei.context.Fault;
import org.rei.context.GainPoint;
import org.rei.context.TestCase;

/**
 * A test case's fault schedule as mission.xml's {@code <fault>} attributes (docs/artifacts.md): the keys of a
 * {@code --fault} spec, which the simulator reads with the same code (rei.sim.faults.spec). Only what the test
 * case says is written: a fault without times acts for the whole run.
 */
final class Faults {

	private Faults() {
	}

	static List<Map<String, String>> of(TestCase testCase) {
		List<Map<String, String>> out = new ArrayList<>();
		for (Fault f : testCase.getOwnedFaults()) {
			Map<String, String> a = new LinkedHashMap<>();
			a.put("sensor", f.getSensor().getLiteral());
			a.put("kind", f.getKind().getLiteral());
			if (f.isSetStart()) {
				a.put("from", Numbers.format(f.getStart()));
			}
			if (f.isSetEnd()) {
				a.put("to", Numbers.format(f.getEnd()));
			}
			if (f.isSetPeriod()) {
				a.put("period", Numbers.format(f.getPeriod()));
				if (f.isSetPulse()) {
					a.put("pulse", Numbers.format(f.getPulse()));
				}
				if (f.isSetDuty()) {
					a.put("duty", Numbers.format(f.getDuty()) + "%");
				}
			}
			if (f.isSetRate()) {
				a.put("rate", Numbers.format(f.getRate()));
			}
			if (f.isSetWidth()) {
				a.put("width", Integer.toString(f.getWidth()));
			}
			if (!f.getOwnedGain().isEmpty()) {
				a.put("gain", gain(f.getOwnedGain()));
			}
			if (f.isSetSigma()) {
				a.put("sigma", Numbers.format(f.getSigma()));
			}
			if (f.isSetAngleFrom()) {
				a.put("angles", Numbers.format(f.getAngleFrom()) + ".." + Numbers.format(f.getAngleTo()));
			}
			if (f.isSetRange()) {
				a.put("range", Numbers.format(f.getRange()));
			}
			if (f.isSetDelay()) {
				a.put("delay", Numbers.format(f.getDelay()));
			}
			if (f.isSetProbability()) {
				a.put("probability", Numbers.format(f.getProbability()));
			}
			if (f.isSetFraction()) {
				a.put("fraction", Numbers.format(f.getFraction()));
			}
			if (f.isSetWheel()) {
				a.put("wheel", f.getWheel().getLiteral());
			}
			if (f.isSetScale()) {
				a.put("scale", Numbers.format(f.getScale()));
			}
			if (f.isSetBias()) {
				a.put("bias", Numbers.format(f.getBias()));
			}
			if (f.isSetDx()) {
				a.put("dx", Numbers.format(f.getDx()));
			}
			if (f.isSetDy()) {
				a.put("dy", Numbers.format(f.getDy()));
			}
			if (f.isSetDyaw()) {
				a.put("dyaw", Numbers.format(f.getDyaw()));
			}
			out.add(a);
		}
		return out;
	}

	/** {@code 0.5}, or {@code 0.2@0/0.8@30} (value@seconds) for a ramp. */
	private static String gain(List<GainPoint> points) {
		if (points.size() == 1 && !points.get(0).isSetAt()) {
			return Numbers.format(points.get(0).getValue());
		}
		return points.stream().map(p -> Numbers.format(p.getValue()) + "@" + Numbers.format(p.getAt()))
				.collect(Collectors.joining("/"));
	}
}
