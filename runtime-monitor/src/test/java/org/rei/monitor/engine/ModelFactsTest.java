/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.kie.api.runtime.KieSession;
import org.kie.api.runtime.rule.Row;
import org.kie.api.runtime.rule.Variable;
import org.kie.api.runtime.rule.ViewChangedEventListener;
import org.rei.runtime.ConcreteObject;
import org.rei.runtime.MissionState;
import org.rei.runtime.RuntimeFactory;
import org.rei.runtime.RuntimeModel;
import org.rei.runtime.TaskState;

/** The model's objects become facts only for classes a pattern matches, and follow the model's changes. */
class ModelFactsTest {

	private static final RuntimeFactory RT = RuntimeFactory.eINSTANCE;

	private static RuntimeModel model() {
		RuntimeModel m = RT.createRuntimeModel();
		m.setOwnedConcreteEnvironment(RT.createConcreteEnvironment());
		for (String name : List.of("tb3", "table", "walker")) {
			ConcreteObject o = RT.createConcreteObject();
			o.setName(name);
			o.setPose(RT.createPose());
			o.setTwist(RT.createTwist());
			m.getOwnedConcreteEnvironment().getOwnedObjects().add(o);
		}
		MissionState mission = RT.createMissionState();
		mission.getOwnedTasks().add(RT.createTaskState());
		mission.getOwnedTasks().add(RT.createTaskState());
		m.setOwnedMissionState(mission);
		return m;
	}

	private static KieSession session(String query) {
		return SessionFactory.build(List.of(new DrlSources.Source("test/q.drl", """
				package rei;
				import org.rei.runtime.ConcreteObject;
				import org.rei.runtime.TaskState;
				""" + query)));
	}

	@Test
	void withoutAPatternOnTheModelNothingOfItIsAFact() {
		KieSession session = session("query q(String target) Proximity( target := object ) end\n"
				.replace("Proximity", "org.rei.monitor.engine.Proximity"));
		assertNull(ModelFacts.attach(session, model()));
		assertEquals(0, session.getFactCount());
	}

	@Test
	void onlyTheMatchedClassIsInsertedAndAddedAndRemovedObjectsFollow() {
		KieSession session = session("query q(double range) TaskState( range := index ) end\n");
		RuntimeModel m = model();
		ModelFacts facts = ModelFacts.attach(session, m);
		assertEquals(2, facts.size()); // the two tasks; not the model, the objects, their poses and twists
		m.getOwnedMissionState().getOwnedTasks().add(RT.createTaskState());
		assertEquals(3, facts.size());
		TaskState first = m.getOwnedMissionState().getOwnedTasks().remove(0);
		assertEquals(2, facts.size());
		assertEquals(2, session.getFactCount());
		first.setIndex(7); // detached: no longer followed
		facts.flush();
		assertEquals(2, session.getFactCount());
	}

	@Test
	void aChangeInsideAPoseUpdatesTheObjectOnceAtTheFlush() {
		KieSession session = session("query movedAway(String target) ConcreteObject( target := name, pose.x > 1 ) end\n");
		RuntimeModel m = model();
		ModelFacts facts = ModelFacts.attach(session, m);
		List<String> rows = new ArrayList<>();
		session.openLiveQuery("movedAway", new Object[] { Variable.v }, new ViewChangedEventListener() {
			@Override
			public void rowInserted(Row row) {
				rows.add("+" + row.get("target"));
			}

			@Override
			public void rowDeleted(Row row) {
				rows.add("-" + row.get("target"));
			}

			@Override
			public void rowUpdated(Row row) {
				rows.add("~" + row.get("target"));
			}
		});
		ConcreteObject walker = m.getOwnedConcreteEnvironment().getOwnedObjects().get(2);
		walker.getPose().setX(2.0);
		walker.getPose().setY(0.5);
		session.fireAllRules();
		assertEquals(List.of(), rows); // marked, not yet told
		facts.flush(); // then the engine fires, as here
		session.fireAllRules();
		assertEquals(List.of("+walker"), rows);
		walker.getPose().setX(0.5);
		facts.flush();
		session.fireAllRules();
		assertEquals(List.of("+walker", "-walker"), rows);
		walker.setPose(RT.createPose()); // a new contained pose: the object is updated, the pose is no fact
		walker.getPose().setX(3.0);
		facts.flush();
		session.fireAllRules();
		assertEquals(List.of("+walker", "-walker", "+walker"), rows);
		assertEquals(3, facts.size());
	}
}
