/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.diagram.Diagram;
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
}
