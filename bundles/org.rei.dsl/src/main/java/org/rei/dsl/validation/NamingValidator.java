/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.HashMap;
import java.util.Map;
import java.util.stream.Stream;

import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.context.NamedElement;
import org.rei.context.SimulationObject;

/** Thesis 4.1.2: each object must have a unique name (floors, walls, objects, humans and the robot alike). */
public class NamingValidator extends ReiCheckBase {

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

	private static String where(NamedElement first) {
		var node = NodeModelUtils.getNode(first);
		return node == null ? " by a floor or wall derived from the room's layout" : " on line " + node.getStartLine();
	}
}
