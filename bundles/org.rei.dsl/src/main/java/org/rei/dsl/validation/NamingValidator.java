/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.HashMap;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.rei.context.ContextPackage;
import org.rei.context.Crowd;
import org.rei.context.Environment;
import org.rei.context.Group;
import org.rei.context.NamedElement;
import org.rei.context.PhysicalObject;
import org.rei.context.SimulationObject;

/**
 * Thesis 4.1.2: each object must have a unique name (floors, walls, objects, humans and the robot alike); the people
 * of a crowd or group, NAME_1 to NAME_N, too.
 */
public class NamingValidator extends ReiCheckBase {

	/** A name that may be one of a crowd's or group's people: the statement's name, '_', a number from 1. */
	private static final Pattern MEMBER = Pattern.compile("(.+)_([1-9][0-9]{0,8})");

	@Check
	public void checkUniqueNames(Environment environment) {
		Map<String, SimulationObject> seen = new HashMap<>();
		Stream<SimulationObject> all = Stream.concat(
				Stream.concat(environment.getOwnedBlocks().stream(), environment.getOwnedObjects().stream()),
				Stream.ofNullable(environment.getOwnedRobot()));
		all.forEach(element -> {
			if (element.getName() == null) {
				return;
			}
			SimulationObject first = seen.putIfAbsent(element.getName(), element);
			if (first != null) {
				errorAt(element, ContextPackage.Literals.NAMED_ELEMENT__NAME, "Duplicate name '" + element.getName()
						+ "': names must be unique in a test case, and it is already used" + where(first),
						ReiIssueCodes.DUPLICATE_NAME);
			}
		});
	}

	/**
	 * A crowd or group names its people NAME_1 to NAME_N (world.json, animation.json): none of those may be a name
	 * the test case declares. One pass over the declared names, whatever the number of people.
	 */
	@Check
	public void checkPeopleNames(Environment environment) {
		if (environment.getOwnedObjects().stream().noneMatch(o -> o instanceof Crowd || o instanceof Group)) {
			return; // a room of a hundred thousand floors is not read through for nothing
		}
		Map<String, Map<Integer, SimulationObject>> numbered = new HashMap<>();
		Stream.concat(Stream.concat(environment.getOwnedBlocks().stream(), environment.getOwnedObjects().stream()),
				Stream.ofNullable(environment.getOwnedRobot())).forEach(element -> {
					Matcher m = element.getName() == null ? null : MEMBER.matcher(element.getName());
					if (m != null && m.matches()) {
						numbered.computeIfAbsent(m.group(1), k -> new HashMap<>())
								.putIfAbsent(Integer.valueOf(m.group(2)), element);
					}
				});
		for (PhysicalObject object : environment.getOwnedObjects()) {
			int count = object instanceof Crowd crowd ? crowd.getCount()
					: object instanceof Group group ? group.getCount() : 0;
			Map<Integer, SimulationObject> taken = object.getName() == null ? null : numbered.get(object.getName());
			if (count < 1 || taken == null) {
				continue;
			}
			taken.entrySet().stream().filter(e -> e.getKey() <= count).min(Map.Entry.comparingByKey()).ifPresent(e -> {
				String what = object instanceof Crowd ? "Crowd" : "Group";
				errorAt(object, ContextPackage.Literals.NAMED_ELEMENT__NAME, what + " '" + object.getName()
						+ "' names its people " + object.getName() + "_1 to " + object.getName() + "_" + count
						+ ", and " + e.getValue().getName() + " is already used" + where(e.getValue()),
						ReiIssueCodes.DUPLICATE_NAME);
			});
		}
	}

	private static String where(NamedElement first) {
		var node = NodeModelUtils.getNode(first);
		return node == null ? " by a floor or wall derived from the room's layout" : " on line " + node.getStartLine();
	}
}
