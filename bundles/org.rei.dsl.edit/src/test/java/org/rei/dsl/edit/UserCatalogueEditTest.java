/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.diagram.Diagram;
import org.rei.dsl.edit.diagram.PaletteType;
import org.rei.dsl.validation.ReiIssueCodes;

/** examples/own_types.rei imports catalogues/office.rei, relative to itself: its types place and draw as others. */
class UserCatalogueEditTest {

	@Test
	void anObjectOfAnImportedTypeIsWrittenAndDrawnWithItsFootprint() {
		RoomDocument document = Texts.open("examples/own_types.rei");
		String original = document.text();

		EditResult result = document.apply(new AddObject("sofa2", "Sofa", "F_3_3"));

		assertEquals(List.of("+    object sofa2 : Sofa on F_3_3"), Texts.diff(original, result.text()));
		assertEquals(List.of(), result.issues());
		Diagram diagram = document.diagram();
		Diagram.Item sofa2 = diagram.objects().get(diagram.objects().size() - 1);
		assertEquals(new Diagram.Footprint("Sofa", "box", 1.1, 0.8, 0.8, "#7A5230"), sofa2.footprint());
		assertEquals(new Diagram.Footprint("Pillar", "cylinder", 0.3, 0.3, 2.5, "#BFBFBF"),
				diagram.objects().get(1).footprint());
		assertEquals("Burger", diagram.robot().footprint().type());
		assertEquals(0.178, diagram.robot().footprint().sizeY());
		Texts.assertReadsBackAsEdited(original, document.uri(), result.text(), new AddObject("sofa2", "Sofa", "F_3_3"));
	}

	/** The imported catalogue's types first, then the default catalogue's. */
	@Test
	void thePaletteHasTheImportedTypesAndTheDefaultOnes() {
		List<PaletteType> palette = Texts.open("examples/own_types.rei").palette();

		assertEquals(List.of("Sofa", "Pillar", "Plant", "Trolley", "Burger", "Floor", "Wall", "Box", "Table", "Chair",
				"Shelf", "Bin", "Cart", "Human", "Waffle"), palette.stream().map(PaletteType::name).toList());
		assertEquals(new PaletteType("Sofa", "object", "box", 1.1, 0.8, "#7A5230"), palette.get(0));
		assertEquals(new PaletteType("Pillar", "object", "cylinder", 0.3, 0.3, "#BFBFBF"), palette.get(1));
		assertEquals(new PaletteType("Trolley", "dynamic", "box", 0.6, 0.4, "#4682B4"), palette.get(3));
		assertEquals(new PaletteType("Burger", "robot", "box", 0.138, 0.178, "#202020"), palette.get(4));
	}

	/** An imported type hides the default type of its name; one without a colour has the metamodel's grey. */
	@Test
	void anImportedTypeHidesTheDefaultTypeOfItsName(@TempDir Path dir) throws IOException {
		Files.writeString(dir.resolve("mine.rei"), "catalogue Mine {\n  type Table : object cylinder 1 x 1 x 0.7\n}\n");
		Path file = dir.resolve("case.rei");
		Files.writeString(file, "import \"mine.rei\"\ntestcase T {\n  room R size 2 x 2 {\n"
				+ "    robot r : Waffle on F_0_0\n  }\n}\n");

		List<PaletteType> palette = RoomDocument.open(file).palette();

		assertEquals(new PaletteType("Table", "object", "cylinder", 1, 1, "#808080"), palette.get(0));
		assertEquals(1, palette.stream().filter(t -> t.name().equals("Table")).count(), palette::toString);
		assertEquals(10, palette.size()); // the default ten, one of them hidden
	}

	@Test
	void aMovingTypeAsFurnitureIsTheValidatorsErrorOnTheObject() {
		RoomDocument document = Texts.open("examples/own_types.rei");

		EditResult result = document.apply(new AddObject("trolley", "Trolley", "F_3_3"));

		ValidationIssue issue = result.issues().get(0);
		assertEquals(List.of(ReiIssueCodes.TYPE_CATEGORY), codes(result));
		assertEquals(List.of("trolley", "object", 11, 22), List.of(issue.element(), issue.kind(), issue.line(),
				issue.column()));
		assertTrue(issue.message().startsWith("Type Trolley is a DYNAMIC type"), issue.message());
	}

	private static List<String> codes(EditResult result) {
		return result.issues().stream().map(ValidationIssue::code).toList();
	}

	/**
	 * examples/corner_desk.rei's desk stands on a polygon: the diagram sends its bounding box's sizes and the
	 * polygon about the item's place (as world.json's footprint), the palette the bounding box; an edit moves it as
	 * any furniture, and a box's footprint has no outline in the JSON.
	 */
	@Test
	void aPolygonTypeIsDrawnAsItsPolygon() {
		RoomDocument document = Texts.open("examples/corner_desk.rei");
		Diagram diagram = document.diagram();
		Diagram.Item desk = diagram.objects().stream().filter(o -> o.name().equals("desk")).findFirst().orElseThrow();
		Diagram.Footprint footprint = desk.footprint();
		assertEquals("polygon", footprint.shape());
		assertEquals(2.2, footprint.sizeX(), 1e-9);
		assertEquals(2.0, footprint.sizeY(), 1e-9);
		assertEquals("polygon", footprint.outline().type());
		double[][] expected = { { -1.1, -1.0 }, { 1.1, -1.0 }, { 1.1, -0.3 }, { -0.4, -0.3 }, { -0.4, 1.0 },
				{ -1.1, 1.0 } };
		for (int i = 0; i < expected.length; i++) {
			org.junit.jupiter.api.Assertions.assertArrayEquals(expected[i], footprint.outline().points()[i], 1e-9);
		}
		String json = org.rei.dsl.edit.diagram.DiagramJson.write(diagram);
		assertTrue(json.contains("\"shape\":\"polygon\""), json);
		assertTrue(json.contains("\"outline\":{\"type\":\"polygon\",\"points\":[[-1.1,-1.0],"), json);
		assertEquals(3, json.split("\"outline\":\\{").length, json); // the desk's and the sofa's only
		PaletteType type = document.palette().stream().filter(t -> t.name().equals("CornerDesk")).findFirst()
				.orElseThrow();
		assertEquals(new PaletteType("CornerDesk", "object", "polygon", 2.2, 2.0, "#A0785A"), type);
	}
}
