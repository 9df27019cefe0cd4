/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rei.monitor.config.CaseReader;
import org.rei.monitor.config.World;
import org.rei.monitor.geometry.Shape;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.wire.RobotState;
import org.rei.monitor.wire.StateMessage;

/**
 * Furniture on a concave polygon (a C-shaped desk whose notch faces the robot): the monitor measures the polygon,
 * so the robot drives into the notch and collides with its back, where a bounding box would have stopped it 0.6 m
 * earlier. The times are checked against an independent oracle: the C as three disjoint rectangles, each measured
 * by Traces' vertex-to-rectangle distances (no JTS).
 */
class PolygonObjectTest {

	/** The desk about its centre (3.5, 1.0), counter-clockwise; its notch 0.7 m wide and 0.6 m deep opens to -x. */
	private static final double[][] C_DESK = { { -0.5, -0.7 }, { 0.5, -0.7 }, { 0.5, 0.7 }, { -0.5, 0.7 },
			{ -0.5, 0.35 }, { 0.1, 0.35 }, { 0.1, -0.35 }, { -0.5, -0.35 } };
	/** The same C as three rectangles {cx, cy, half x, half y} in the world: its back and its two arms. */
	private static final double[][] PIECES = { { 3.8, 1.0, 0.2, 0.7 }, { 3.3, 1.525, 0.3, 0.175 },
			{ 3.3, 0.475, 0.3, 0.175 } };
	private static final double STOP = 3.6 - Traces.HALF_X; // the robot's front at the notch's back

	/** The robot drives from x = 1 along y = 1 at 0.2 m/s into the notch until it touches, then backs out. */
	private static double robotX(double t) {
		return t <= 14 ? Math.min(1.0 + 0.2 * t, STOP) : STOP - 0.15 * (t - 14);
	}

	private static double oracle(double t) {
		double best = Double.POSITIVE_INFINITY;
		for (double[] p : PIECES) {
			best = Math.min(best, Traces.rectangles(new double[] { robotX(t), 1.0, 0 }, Traces.HALF_X, 0.153,
					new double[] { p[0], p[1], 0 }, p[2], p[3]));
		}
		return best;
	}

	private static CaseReader.Case withDesk() {
		CaseReader.Case room = TestRuns.room();
		List<World.WorldObject> objects = new ArrayList<>();
		for (World.WorldObject o : room.world().objects()) {
			objects.add(!o.name().equals("table1") ? o
					: new World.WorldObject("desk", "STATIC", "CornerDesk", "POLYGON", new double[] { 1.0, 1.4, 0.75 },
							new double[] { 3.5, 1.0, 0.375, 0 }, o.floor(), Shape.polygon(C_DESK)));
		}
		World w = room.world();
		org.rei.monitor.config.MonitorSpec m = room.monitor();
		List<org.rei.monitor.config.MonitorSpec.CatalogueEntry> types = new ArrayList<>(m.catalogue());
		types.add(new org.rei.monitor.config.MonitorSpec.CatalogueEntry("CornerDesk", "STATIC", "POLYGON",
				new double[] { 1.0, 1.4, 0.75 }, 30));
		return new CaseReader.Case(new World(w.testcase(), w.environment(), w.floorSize(), w.floors(), objects,
				w.robot()), new org.rei.monitor.config.MonitorSpec(m.testcase(), m.robot(), m.epsClose(),
						m.epsCollision(), m.topics(), types));
	}

	@Test
	void theRobotMeetsTheNotchsBackAtTheOraclesTimes() {
		List<StateMessage> trace = new ArrayList<>();
		for (int k = 0; k <= 400; k++) {
			double t = k * Traces.DT;
			double x = robotX(t);
			List<String[]> contacts = x >= STOP - 1e-12 ? List.<String[]>of(new String[] { "tb3", "desk" }) : List.of();
			trace.add(new StateMessage(k, t, k == 0, List.of(),
					new RobotState("tb3", x, 1.0, 0, 0, 0, 0, 0, null, Double.NaN, null, null, Double.NaN), contacts));
		}
		try (TestRuns run = new TestRuns(withDesk())) {
			trace.forEach(run.monitor::onState);
			assertEquals(List.of("SIG_GEOM_FAR_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_COLLISION",
					"SIG_GEOM_COLLISION_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_FAR"), run.names("SIG_GEOM_"));
			// the thresholds are the test room's, as in ScriptedTraceTest: close 0.25, collision 0.01
			List<double[]> exact = ScriptedTraceTest.crossings(PolygonObjectTest::oracle, 20);
			assertEquals(4, exact.size());
			List<Signal> geom = run.of("SIG_GEOM_");
			for (int i = 0; i < 4; i++) {
				Signal s = geom.get(i);
				ScriptedTraceTest.assertWithinOneSample(exact.get(i)[0], s);
				assertEquals("desk", s.object());
				assertEquals(oracle(s.t()), s.distance(), 1e-9, s.toString());
			}
			// in the notch: COLLISION with the robot's front at the notch's back, 0.6 m past the bounding box's face
			assertTrue(robotX(geom.get(1).t()) + Traces.HALF_X > 3.5, geom.get(1).toString());
			// the runtime model's desk has its type's polygon (for queries over the model)
			var desk = run.monitor.model().model().getOwnedConcreteEnvironment().getOwnedObjects().stream()
					.filter(o -> o.getName().equals("desk")).findFirst().orElseThrow();
			assertEquals(org.rei.catalogue.Shape.POLYGON, desk.getType().getShape());
			assertEquals(C_DESK.length, desk.getType().getVertices().size());
			assertEquals(0.1, desk.getType().getVertices().get(5).getX(), 1e-12);
		}
	}
}
