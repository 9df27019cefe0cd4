/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rei.catalogue.ObjectCategory;
import org.rei.context.Floor;
import org.rei.context.Human;
import org.rei.context.StaticObject;
import org.rei.monitor.config.CaseReader;
import org.rei.monitor.pipeline.TestRuns;
import org.rei.monitor.pipeline.TracesAccess;
import org.rei.monitor.wire.MissionMessage;
import org.rei.monitor.wire.StateMessage;
import org.rei.runtime.ConcreteObject;
import org.rei.runtime.NavigationState;
import org.rei.runtime.RuntimeModel;
import org.rei.runtime.TaskStatus;

class RuntimeModelTest {

	private static RuntimeModelUpdater fresh() {
		CaseReader.Case c = TestRuns.room();
		return RuntimeModelUpdater.create("r1", c.world(), c.monitor());
	}

	@Test
	void abstractEnvironmentIsRebuiltFromTheFloorCells() {
		RuntimeModelUpdater u = fresh();
		RuntimeModel m = u.model();
		List<Floor> floors = m.getOwnedAbstractEnvironment().getOwnedBlocks().stream()
				.filter(Floor.class::isInstance).map(Floor.class::cast).toList();
		assertEquals(24, floors.size());
		Floor f00 = floors.stream().filter(f -> f.getName().equals("F_0_0")).findFirst().orElseThrow();
		assertEquals("F_0_1", f00.getTop().getName());
		assertEquals("F_1_0", f00.getRight().getName());
		// table1 at (1.5, 2.5) stands on F_1_2; its type comes from the catalogue
		StaticObject table = (StaticObject) u.abstractObject("table1");
		assertEquals("F_1_2", table.getFloor().getName());
		assertEquals("Table", table.getType().getName());
		assertEquals(ObjectCategory.STATIC, u.object("table1").getCategory());
		assertEquals("F_1_2", u.object("table1").getStandsOn().getName());
		assertTrue(u.abstractObject("h1") instanceof Human);
	}

	@Test
	void stateMessagesMoveObjectsAcrossFloors() {
		RuntimeModelUpdater u = fresh();
		List<StateMessage> trace = TracesAccess.humanCrossing();
		assertEquals("F_3_3", u.abstractObject("h1").getFloor().getName()); // world.json: (3.5, 3.5)
		u.applyState(trace.get(10)); // t = 0.5: human at (4.0, 3.5)
		assertEquals("F_4_3", u.abstractObject("h1").getFloor().getName());
		assertEquals("F_4_3", u.object("h1").getStandsOn().getName());
		u.applyState(trace.get(60)); // t = 3.0: human at (4.0, 1.0), robot at (3.6, 1.0)
		assertEquals("F_4_1", u.abstractObject("h1").getFloor().getName());
		assertEquals("F_3_1", u.abstractRobot().getFloor().getName());
		u.applyState(trace.get(0)); // t = 0: human at (4.0, 4.0), on the room's edge: no floor under it
		assertEquals(null, u.abstractObject("h1").getFloor());
	}

	@Test
	void robotDescriptionFollowsOdometryLaserAndNavigation() {
		RuntimeModelUpdater u = fresh();
		List<StateMessage> trace = TracesAccess.wallApproach();
		for (StateMessage s : trace.subList(0, 101)) {
			u.applyState(s);
		}
		RuntimeModel m = u.model();
		assertEquals(5.0, m.getTime(), 1e-12);
		ConcreteObject body = m.getOwnedRobot().getBody();
		assertSame(u.object("tb3"), body);
		assertEquals(5.0, body.getPose().getX(), 1e-12);
		assertEquals("F_5_1", body.getStandsOn().getName());
		assertEquals("F_5_1", u.abstractRobot().getFloor().getName());
		assertEquals(5.0, m.getOwnedRobot().getOdometry().getX(), 1e-12);
		assertEquals(1.0, m.getOwnedRobot().getLaserMin(), 1e-12);
		assertEquals(NavigationState.ACTIVE, m.getOwnedRobot().getNavigationState());
		u.applyMission(new MissionMessage(0, 1.0, "TASK_START", 0, new double[] { 5.8, 1.0, 0 }, null));
		u.applyMission(new MissionMessage(1, 9.0, "TASK_FAIL", 0, new double[] { 5.8, 1.0, 0 }, "timeout"));
		assertEquals(TaskStatus.FAILED, m.getOwnedMissionState().getOwnedTasks().get(0).getStatus());
		assertEquals("timeout", m.getOwnedMissionState().getOwnedTasks().get(0).getReason());
	}

	@Test
	void xmiSnapshotReloadsIntoEmf() {
		RuntimeModelUpdater u = fresh();
		for (StateMessage s : TracesAccess.humanCrossing().subList(0, 40)) {
			u.applyState(s);
		}
		String xmi = Snapshots.toXmi(u.resource());
		RuntimeModel back = Snapshots.load(xmi);
		assertEquals("r1", back.getRunId());
		assertEquals(u.model().getTime(), back.getTime(), 0);
		assertEquals(u.model().getOwnedConcreteEnvironment().getOwnedObjects().size(),
				back.getOwnedConcreteEnvironment().getOwnedObjects().size());
		ConcreteObject h1 = back.getOwnedConcreteEnvironment().getOwnedObjects().stream()
				.filter(o -> o.getName().equals("h1")).findFirst().orElseThrow();
		assertEquals(u.object("h1").getPose().getY(), h1.getPose().getY(), 0);
		assertNotNull(h1.getType());
		assertEquals("Human", h1.getType().getName()); // the catalogue travels in the snapshot
		assertEquals(u.object("h1").getStandsOn().getName(), h1.getStandsOn().getName());
		assertEquals("tb3", back.getOwnedRobot().getBody().getName());
		assertEquals(Snapshots.toXmi(u.resource()), xmi, "a snapshot does not change the model");
	}
}
