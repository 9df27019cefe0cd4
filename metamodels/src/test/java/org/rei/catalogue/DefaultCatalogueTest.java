/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.catalogue;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.eclipse.emf.common.util.Diagnostic;
import org.junit.jupiter.api.Test;
import org.rei.catalogue.util.Catalogues;

class DefaultCatalogueTest {

	private final Catalogue catalogue = Catalogues.loadDefault(new ResourceSetImpl());

	@Test
	void hasTheTypesTheIssueAsksFor() {
		for (String name : List.of("Wall", "Floor", "Box", "Table", "Chair", "Shelf", "Human", "Waffle")) {
			assertTrue(Catalogues.find(catalogue, name).isPresent(), "missing type " + name);
		}
	}

	@Test
	void waffleIsADifferentialDriveRobotWithA360BeamLidar() {
		RobotType waffle = assertInstanceOf(RobotType.class, Catalogues.find(catalogue, "Waffle").orElseThrow());
		assertEquals(ObjectCategory.ROBOT, waffle.getCategory());
		assertEquals(0.281, waffle.getSizeX(), 1e-9);
		assertEquals(0.306, waffle.getSizeY(), 1e-9);
		assertEquals(360, waffle.getLidar().getBeams());
		assertEquals(0.287, waffle.getWheelSeparation(), 1e-9);
	}

	@Test
	void humansAreCylinders() {
		ObjectType human = Catalogues.find(catalogue, "Human").orElseThrow();
		assertEquals(ObjectCategory.HUMAN, human.getCategory());
		assertEquals(Shape.CYLINDER, human.getShape());
	}

	@Test
	void isValidAgainstItsMetamodel() {
		assertEquals(Diagnostic.OK, Diagnostician.INSTANCE.validate(catalogue).getSeverity());
	}
}
