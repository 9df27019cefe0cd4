/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleUnaryOperator;

import org.junit.jupiter.api.Test;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.wire.StateMessage;

/** Scripted traces yield exactly the expected transitions, each within one sample of the exact crossing time. */
class ScriptedTraceTest {

	private static final double CLOSE = 0.25;
	private static final double COLLISION = 0.01;

	private static TestRuns run(List<StateMessage> trace) {
		TestRuns run = new TestRuns();
		for (StateMessage m : trace) {
			run.monitor.onState(m);
		}
		return run;
	}

	/** Times at which the state (FAR 0, CLOSE 1, COLLISION 2) of gap(t) changes, on a 0.1 ms grid. */
	static List<double[]> crossings(DoubleUnaryOperator gap, double end) {
		List<double[]> out = new ArrayList<>();
		int state = state(gap.applyAsDouble(0));
		for (double t = 0; t <= end; t += 1e-4) {
			int s = state(gap.applyAsDouble(t));
			if (s != state) {
				out.add(new double[] { t, state, s });
				state = s;
			}
		}
		return out;
	}

	private static int state(double d) {
		return d < COLLISION ? 2 : d < CLOSE ? 1 : 0;
	}

	static void assertWithinOneSample(double exact, Signal s) {
		assertTrue(s.t() >= exact - 1e-3 && s.t() < exact + Traces.DT + 1e-3,
				s + " should come within one sample after " + exact);
	}

	@Test
	void robotDrivingIntoAWallAndBackPassesEveryGeometricState() {
		try (TestRuns run = run(Traces.wallApproach())) {
			List<Signal> geom = run.of("SIG_GEOM_");
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_COLLISION",
					"SIG_GEOM_COLLISION_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_FAR"), run.names("SIG_GEOM_"));
			// hand-computed: gap = 1.8595 - 0.2 t going in, 0.15 (t - 10) coming back
			double[] expected = { 8.05, 9.25, 10.10, 11.70 };
			double[] distance = { 0.2495, 0.0095, 0.015, 0.255 };
			for (int i = 0; i < 4; i++) {
				assertEquals(expected[i], geom.get(i).t(), 1e-9, geom.get(i).toString());
				assertEquals(distance[i], geom.get(i).distance(), 1e-9, geom.get(i).toString());
				assertEquals("tb3", geom.get(i).subject());
				assertEquals("wall_east", geom.get(i).object());
			}
			List<double[]> exact = crossings(Traces::wallGap, 14);
			assertEquals(4, exact.size());
			for (int i = 0; i < 4; i++) {
				assertWithinOneSample(exact.get(i)[0], geom.get(i));
			}
		}
	}

	@Test
	void laserSeesTheWallAtTheSameTimesAsTheGeometry() {
		try (TestRuns run = run(Traces.wallApproach())) {
			assertEquals(List.of("SIG_LASER_FAR_TRANSIT_CLOSE", "SIG_LASER_CLOSE_TRANSIT_COLLISION",
					"SIG_LASER_COLLISION_TRANSIT_CLOSE", "SIG_LASER_CLOSE_TRANSIT_FAR"), run.names("SIG_LASER_"));
			List<Double> times = run.of("SIG_LASER_").stream().map(Signal::t).toList();
			assertEquals(List.of(8.05, 9.25, 10.10, 11.70), times.stream().map(t -> Math.round(t * 100) / 100.0).toList());
			assertTrue(run.of("SIG_LASER_").stream().allMatch(s -> s.object().equals("laser")));
			assertEquals(10, run.signals.size(), run.signals.toString()); // + the wall's per-object begin and end
		}
	}

	@Test
	void transitionsFireByRuleNameOncePerChange() {
		try (TestRuns run = run(Traces.wallApproach())) {
			assertEquals(List.of("Robot goes from far to close", "Robot goes from close to collision",
					"Robot starts colliding with an object", "Robot goes from collision to close",
					"Robot stops colliding with an object", "Robot goes from close to far"),
					run.firedRules.stream().filter(r -> r.startsWith("Robot")).toList());
			assertEquals(List.of("Laser starts sensing closeness", "Laser goes from closeness to collision",
					"Laser goes from collision to closeness", "Laser stops sensing closeness"),
					run.firedRules.stream().filter(r -> r.startsWith("Laser")).toList());
		}
	}

	@Test
	void circleAroundATableIsCloseAtItsShortSidesOnly() {
		double end = 2 * Math.PI * 0.95 / 0.2;
		DoubleUnaryOperator gap = t -> Traces.rectangles(Traces.circlePose(t), 0.1405, 0.153,
				new double[] { 1.5, 2.5, 0 }, 0.6, 0.4);
		try (TestRuns run = run(Traces.circleAroundTable())) {
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_FAR",
					"SIG_GEOM_FAR_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_FAR"), run.names("SIG_GEOM_"));
			List<double[]> exact = crossings(gap, end);
			assertEquals(4, exact.size());
			List<Signal> geom = run.of("SIG_GEOM_");
			for (int i = 0; i < 4; i++) {
				assertWithinOneSample(exact.get(i)[0], geom.get(i));
				assertEquals("table1", geom.get(i).object());
				assertEquals(gap.applyAsDouble(geom.get(i).t()), geom.get(i).distance(), 1e-9);
			}
			assertEquals(List.of(), run.names("SIG_LASER_"), "no laser data in this trace");
		}
	}

	@Test
	void humanCrossingThePathIsApproachedHitAndLeft() {
		DoubleUnaryOperator gap = t -> {
			double[] r = Traces.crossingRobot(t);
			double[] h = Traces.crossingHuman(t);
			return Math.max(0, Traces.pointToRectangle(h[0], h[1], r[0], r[1], r[2], 0.1405, 0.153) - 0.25);
		};
		try (TestRuns run = run(Traces.humanCrossing())) {
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_COLLISION",
					"SIG_GEOM_COLLISION_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_FAR"), run.names("SIG_GEOM_"));
			List<double[]> exact = crossings(gap, 6);
			assertEquals(4, exact.size());
			List<Signal> geom = run.of("SIG_GEOM_");
			for (int i = 0; i < 4; i++) {
				assertWithinOneSample(exact.get(i)[0], geom.get(i));
				assertEquals("h1", geom.get(i).object());
			}
			// the per-object queries saw the same: closeness found and lost twice around one collision (events of
			// different queries at the same time come in no defined order, so each query is checked on its own)
			assertEquals(List.of("FOUND", "LOST", "FOUND", "LOST"), kinds(run, "closeToObject"));
			assertEquals(List.of("FOUND", "LOST"), kinds(run, "collisionWithObject"));
			double collisionFound = run.queryEvents.stream().filter(e -> e.getQuery().equals("collisionWithObject"))
					.findFirst().orElseThrow().getT();
			assertEquals(geom.get(1).t(), collisionFound, 0);
		}
	}

	@Test
	void aHumanBumpingARobotThatTouchesAWallIsAPerObjectCollisionAndNoNewRobotLevelOne() {
		// the human's circle (r 0.25) reaches the robot's west face (x = 6 - 0.281) within the collision threshold
		DoubleUnaryOperator gap = t -> 6.0 - 2 * Traces.HALF_X - (Traces.bumpingHumanX(t) + 0.25);
		try (TestRuns run = run(Traces.humanBumpsRobotAtWall())) {
			// Table 2: the robot is in COLLISION (with the wall) from its first message, and stays there
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_COLLISION"), run.names("SIG_GEOM_"));
			List<Signal> perObject = run.of("SIG_OBJECT_");
			assertEquals(List.of("SIG_OBJECT_COLLISION_BEGIN wall_east", "SIG_OBJECT_COLLISION_BEGIN h1",
					"SIG_OBJECT_COLLISION_END h1"), perObject.stream().map(s -> s.signal() + " " + s.object()).toList());
			List<double[]> exact = crossings(gap, 8); // FAR->CLOSE->COLLISION->CLOSE->FAR of the human alone
			assertEquals(4, exact.size());
			assertWithinOneSample(exact.get(1)[0], perObject.get(1));
			assertWithinOneSample(exact.get(2)[0], perObject.get(2));
		}
	}

	@Test
	void aMovingObjectLeftOutOfTheFullFramesIsNotJudgedUntilItAppears() {
		try (TestRuns run = run(Traces.unpublishedHuman(Double.POSITIVE_INFINITY))) {
			// h1 stands in world.json where the robot drives through; unpublished, its place there says nothing
			assertEquals(List.of(), run.names("SIG_GEOM_"));
			assertEquals(List.of(), run.of("SIG_OBJECT_"));
		}
		try (TestRuns run = run(Traces.unpublishedHuman(7.0))) {
			// from t = 7 the collector publishes it again: the robot (x = 3.4, reaching 3.54) is then inside it
			List<Signal> geom = run.of("SIG_GEOM_");
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_COLLISION"),
					geom.stream().limit(2).map(Signal::signal).toList());
			assertEquals(7.0, geom.get(0).t(), 1e-9);
			assertEquals("h1", geom.get(1).object());
		}
	}

	private static List<String> kinds(TestRuns run, String query) {
		return run.queryEvents.stream().filter(e -> "h1".equals(e.getTarget()) && e.getQuery().equals(query))
				.map(e -> e.getKind().name()).toList();
	}

	@Test
	void signalsAreNumberedWithoutGaps() {
		try (TestRuns run = run(Traces.wallApproach())) {
			for (int i = 0; i < run.signals.size(); i++) {
				assertEquals(i, run.signals.get(i).seq());
			}
		}
	}
}
