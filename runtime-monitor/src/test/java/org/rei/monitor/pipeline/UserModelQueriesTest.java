/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rei.monitor.engine.DrlSources;
import org.rei.monitor.engine.PatternRules;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.wire.MissionMessage;
import org.rei.monitor.wire.RobotState;
import org.rei.monitor.wire.StateMessage;
import org.rei.vepl.compiler.VeplLoader;

/** A user's query over the EMF runtime model, named by a user's pattern, fires from the model's changes. */
class UserModelQueriesTest {

	private static final String QUERIES = """
			package rei;

			import org.rei.runtime.ConcreteObject;
			import org.rei.runtime.RobotDescription;
			import org.rei.runtime.TaskState;
			import org.rei.runtime.TaskStatus;

			query robotStillInTask(String subject)
			    RobotDescription( subject := name, $body : body )
			    ConcreteObject( this == $body, Math.abs(twist.vx) < 0.01, Math.abs(twist.vy) < 0.01,
			                    Math.abs(twist.wz) < 0.01 )
			    exists TaskState( status == TaskStatus.ACTIVE )
			end

			query odometryDrifted(String subject)
			    RobotDescription( subject := name, $body : body, $odometry : odometry )
			    ConcreteObject( this == $body, Math.hypot(pose.x - $odometry.x, pose.y - $odometry.y) > 0.3 )
			end
			""";

	private static final String PATTERNS = """
			queryEvent stillInTask as robotStillInTask found
			queryEvent movesOrTaskOver as robotStillInTask lost
			complexEvent stillFor5s() { as (stillInTask -> NOT movesOrTaskOver)[5000] }
			signal SIG_STILL_IN_TASK
			rule "stands still in a task for 5 s" on stillFor5s emits SIG_STILL_IN_TASK

			queryEvent drifted as odometryDrifted found
			signal SIG_ODOMETRY_DRIFT
			rule "odometry drifted" on drifted emits SIG_ODOMETRY_DRIFT
			""";

	private static TestRuns run() throws Exception {
		List<DrlSources.Source> queries = new ArrayList<>(DrlSources.packaged(DrlSources.QUERIES));
		DrlSources.Source own = new DrlSources.Source("user/model.drl", QUERIES);
		queries.add(own);
		// compiled with the defaults, as the monitor does: one declaration of how long events are kept, for the
		// longest window of them all (the 5 s here)
		List<VeplLoader.Source> patterns = new ArrayList<>(PatternRules.packaged());
		patterns.add(new VeplLoader.Source("user.vepl", PATTERNS));
		List<DrlSources.Source> rules = new ArrayList<>(queries);
		rules.addAll(PatternRules.compile(patterns, queries));
		return new TestRuns(rules);
	}

	/**
	 * 20 Hz, 12 s: the robot stands at (1, 1) until t = 8, then drives at 0.2 m/s; its odometry slips away at
	 * 0.1 m/s from t = 2.02 (0.3 m at t = 5.02). The task starts at t = 1.
	 */
	private static void drive(TestRuns run) {
		run.monitor.onMission(new MissionMessage(0, 0.0, "BEGIN", -1, null, null));
		for (int k = 0; k <= 240; k++) {
			double t = k * Traces.DT;
			if (k == 20) {
				run.monitor.onMission(new MissionMessage(1, t, "TASK_START", 0, new double[] { 3, 1, 0 }, null));
			}
			double x = t <= 8 ? 1.0 : 1.0 + 0.2 * (t - 8);
			double vx = t < 8 ? 0 : 0.2;
			double odomX = x + Math.max(0, 0.1 * (t - 2.02));
			RobotState robot = new RobotState("tb3", x, 1.0, 0, 0, vx, 0, 0, new double[] { odomX, 1.0, 0 },
					Double.NaN, null, "ACTIVE", Double.NaN);
			run.monitor.onState(new StateMessage(k, t, k == 0, List.of(), robot, List.of()));
		}
	}

	@Test
	void standingStillFiveSecondsInATaskAndAnOdometryDriftAreSignalled() throws Exception {
		try (TestRuns run = run()) {
			drive(run);
			List<Signal> still = run.of("SIG_STILL_IN_TASK");
			assertEquals(1, still.size(), () -> run.signals.toString());
			// found with the task's start at t = 1; the window's NOT holds until the clock passes 6.0: the next sample
			assertEquals(6.05, still.get(0).t(), 1e-9);
			assertEquals("tb3", still.get(0).subject());
			assertEquals("", still.get(0).object()); // the query declares no target and no range
			assertEquals(0.0, still.get(0).distance());
			List<Signal> drift = run.of("SIG_ODOMETRY_DRIFT");
			assertEquals(1, drift.size());
			assertEquals(5.05, drift.get(0).t(), 1e-9); // the first sample beyond 0.3 m
		}
	}
}
