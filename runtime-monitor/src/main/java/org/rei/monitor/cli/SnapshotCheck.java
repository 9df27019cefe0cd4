/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.cli;

import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.rei.monitor.model.Snapshots;
import org.rei.runtime.ConcreteObject;
import org.rei.runtime.RuntimeModel;
import org.rei.runtime.TaskState;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Reloads an XMI snapshot (the {@code snapshot} RPC's result or the file written on exit) into EMF and prints what
 * it holds as one JSON object, for checks from other languages:
 * {@code java -cp rei-monitor.jar org.rei.monitor.cli.SnapshotCheck FILE}. Exit 0 when it loads with every
 * reference resolved, 1 otherwise (the reason on stderr), 2 for a bad command line.
 */
public final class SnapshotCheck {

	private SnapshotCheck() {
	}

	public static void main(String[] args) {
		System.exit(run(args, System.out, System.err));
	}

	static int run(String[] args, PrintStream out, PrintStream err) {
		if (args.length != 1) {
			err.println("usage: java -cp rei-monitor.jar org.rei.monitor.cli.SnapshotCheck SNAPSHOT.xmi");
			return 2;
		}
		try {
			RuntimeModel model = Snapshots.load(Files.readString(Path.of(args[0]), StandardCharsets.UTF_8));
			int unresolved = EcoreUtil.UnresolvedProxyCrossReferencer.find(model.eResource()).size();
			if (unresolved > 0) {
				err.println("snapshot-check: " + unresolved + " unresolved reference(s)");
				return 1;
			}
			out.println(new ObjectMapper().writeValueAsString(summary(model)));
			return 0;
		} catch (Exception e) {
			err.println("snapshot-check: " + e);
			return 1;
		}
	}

	static Map<String, Object> summary(RuntimeModel model) {
		Map<String, Object> s = new LinkedHashMap<>();
		s.put("runId", model.getRunId());
		s.put("time", model.getTime());
		List<ConcreteObject> objects = model.getOwnedConcreteEnvironment().getOwnedObjects();
		s.put("concreteObjects", objects.size());
		s.put("untypedObjects", objects.stream().filter(o -> o.getType() == null).map(ConcreteObject::getName).toList());
		s.put("abstractObjects", model.getOwnedAbstractEnvironment().getOwnedObjects().size());
		ConcreteObject body = model.getOwnedRobot().getBody();
		Map<String, Object> robot = new LinkedHashMap<>();
		robot.put("name", body.getName());
		robot.put("type", body.getType() == null ? null : body.getType().getName());
		robot.put("pose", List.of(body.getPose().getX(), body.getPose().getY(), body.getPose().getZ(),
				body.getPose().getYaw()));
		robot.put("standsOn", body.getStandsOn() == null ? null : body.getStandsOn().getName());
		robot.put("laserMin", model.getOwnedRobot().getLaserMin());
		robot.put("laserClearance", model.getOwnedRobot().getLaserClearance());
		robot.put("navigationState", String.valueOf(model.getOwnedRobot().getNavigationState()));
		s.put("robot", robot);
		s.put("missionBegun", model.getOwnedMissionState().isBegun());
		s.put("missionEnded", model.getOwnedMissionState().isEnded());
		s.put("tasks", model.getOwnedMissionState().getOwnedTasks().stream().map(SnapshotCheck::task).toList());
		return s;
	}

	private static Map<String, Object> task(TaskState t) {
		Map<String, Object> m = new LinkedHashMap<>();
		m.put("index", t.getIndex());
		m.put("status", String.valueOf(t.getStatus()));
		return m;
	}
}
