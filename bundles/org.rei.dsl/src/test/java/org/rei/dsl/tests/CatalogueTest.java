/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.xtext.testing.InjectWith;
import org.eclipse.xtext.testing.extensions.InjectionExtension;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.Lidar;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.RobotType;
import org.rei.catalogue.Shape;
import org.rei.context.StaticObject;
import org.rei.context.TestCase;

import com.google.inject.Inject;

/** A user catalogue's declarations become catalogue types, and a test case that imports it links to them. */
@ExtendWith(InjectionExtension.class)
@InjectWith(ReiInjectorProvider.class)
class CatalogueTest {

	private static final Path OFFICE = Path.of("src/test/resources/catalogues/office.rei").toAbsolutePath();

	@Inject
	private ReiFiles files;

	@Test
	void declarationsBecomeTypesWithEveryParameter() {
		Catalogue office = (Catalogue) files.load(OFFICE).getContents().get(0);
		assertEquals(List.of("Sofa", "Pillar", "Scout"), office.getOwnedTypes().stream().map(t -> t.getName()).toList());
		var sofa = office.getOwnedTypes().get(0);
		assertEquals(ObjectCategory.STATIC, sofa.getCategory());
		assertEquals(List.of(1.1, 0.8, 0.8, 40.0), List.of(sofa.getSizeX(), sofa.getSizeY(), sofa.getSizeZ(), sofa.getMass()));
		assertEquals("#7A5230", sofa.getColour());
		assertEquals(Shape.CYLINDER, office.getOwnedTypes().get(1).getShape());
		RobotType scout = (RobotType) office.getOwnedTypes().get(2);
		assertEquals(ObjectCategory.ROBOT, scout.getCategory());
		assertEquals(Shape.BOX, scout.getShape());
		assertEquals(List.of(0.04, 0.22, 0.5, 2.0), List.of(scout.getWheelRadius(), scout.getWheelSeparation(),
				scout.getMaxLinearVelocity(), scout.getMaxAngularVelocity()));
		Lidar lidar = scout.getLidar();
		assertEquals(720, lidar.getBeams());
		assertEquals(List.of(0.05, 8.0, 15.0, 0.18), List.of(lidar.getRangeMin(), lidar.getRangeMax(), lidar.getRate(),
				lidar.getMountHeight()));
		assertEquals(List.of(), files.validate(OFFICE));
	}

	@Test
	void anImportingTestCaseUsesTheUserTypesBesideTheDefaultOnes(@TempDir Path dir) throws IOException {
		Path file = dir.resolve("case.rei");
		Files.writeString(file, """
				import "%s"
				testcase T {
				  room R size 3 x 2 {
				    object sofa : Sofa on F_1_0
				    object desk : Table on F_2_0
				    robot r : Scout on F_0_0
				  }
				  mission M { goto F_1_1 goto F_2_1 }
				}
				""".formatted(dir.relativize(OFFICE).toString().replace('\\', '/')));
		List<Issue> issues = files.validate(file);
		assertEquals(List.of(), issues);
		TestCase testCase = files.testCase(file);
		StaticObject sofa = (StaticObject) testCase.getOwnedEnvironment().getOwnedObjects().get(0);
		StaticObject desk = (StaticObject) testCase.getOwnedEnvironment().getOwnedObjects().get(1);
		assertTrue(sofa.getType().eResource().getURI().toFileString().endsWith("office.rei"));
		assertTrue(desk.getType().eResource().getURI().toString().endsWith("default.catalogue"));
		assertEquals("Scout", testCase.getOwnedEnvironment().getOwnedRobot().getType().getName());
	}

	/** A polygon type's vertices, as written (negative and decimal numbers), its height; the example validates. */
	@Test
	void aPolygonTypeKeepsItsVertices(@TempDir Path dir) throws IOException {
		Path file = dir.resolve("shapes.rei");
		Files.writeString(file, """
				catalogue Shapes {
				  type Wedge : object polygon (-0.5,-0.25) (0.5, -0.25)( 0 , 0.75 ) height 0.4 colour "#808080"
				}
				""");
		Catalogue shapes = (Catalogue) files.load(file).getContents().get(0);
		var wedge = shapes.getOwnedTypes().get(0);
		assertEquals(Shape.POLYGON, wedge.getShape());
		assertEquals(List.of(-0.5, -0.25, 0.5, -0.25, 0.0, 0.75), wedge.getVertices().stream()
				.flatMap(v -> java.util.stream.Stream.of(v.getX(), v.getY())).toList());
		assertEquals(0.4, wedge.getSizeZ());
		assertEquals("**Wedge** (STATIC): polygon of 3 vertices, 0.5 m^2, 1 x 1 m, 0.4 m high, 0 kg",
				new org.rei.dsl.documentation.ReiDocumentationProvider().getDocumentation(wedge));
		assertEquals(List.of(), files.validate(file));
		assertEquals(List.of(), files.validate(ReiFiles.repository().resolve("examples/corner_desk.rei")));
	}
}
