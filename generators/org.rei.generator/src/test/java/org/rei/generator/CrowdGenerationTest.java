/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.context.Crowd;
import org.rei.context.Group;
import org.rei.context.TestCase;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Crowds and groups are expanded into the people they are (docs/artifacts.md): HUMAN bodies in world.json and
 * world.sdf where they stand, entries of animation.json's people; the simulation sees only single people.
 */
class CrowdGenerationTest {

	private static final ObjectMapper JSON = new ObjectMapper();
	private static ArtifactGenerator generator;

	@TempDir
	Path out;

	@BeforeAll
	static void parseTemplatesOnce() {
		generator = new ArtifactGenerator(GeneratorOptions.defaults());
	}

	/**
	 * The crowd's people stand on its from floors' lattice (row by row from the bottom-left, 0.6 m apart, 0.3 m in
	 * from the edge, the left wall's face at 0.05 m) and walk to the to floors' points in turn (here one, shared), one every 1 / rate s; the group's leader stands on
	 * the first stop's centre and its follower at the nearest point beside it; speed ranges as speed and speedTo.
	 */
	@Test
	void crowdsAndGroupsAreListedPersonByPerson() throws Exception {
		generator.generate(TestCases.withCrowds(), out);

		String text = Files.readString(out.resolve("animation.json"));
		assertEquals("""
				  "people": [
				    {"name": "shoppers_1", "behaviour": "scared", "speed": 1.0, "speedTo": 1.4, "start": 0.0, "loop": true,
				     "route": [{"floor": "F_0_1", "x": 0.35, "y": 1.3, "wait": 0.0}, {"floor": "F_7_1", "x": 7.3, "y": 1.3, "wait": 0.0}]},
				    {"name": "shoppers_2", "behaviour": "scared", "speed": 1.0, "speedTo": 1.4, "start": 0.5, "loop": true,
				     "route": [{"floor": "F_0_1", "x": 0.35, "y": 1.9, "wait": 0.0}, {"floor": "F_7_1", "x": 7.3, "y": 1.3, "wait": 0.0}]},
				    {"name": "shoppers_3", "behaviour": "scared", "speed": 1.0, "speedTo": 1.4, "start": 1.0, "loop": true,
				     "route": [{"floor": "F_0_2", "x": 0.35, "y": 2.5, "wait": 0.0}, {"floor": "F_7_1", "x": 7.3, "y": 1.3, "wait": 0.0}]},
				    {"name": "family_1", "behaviour": "avoids", "speed": 1.2, "start": 1.0, "loop": false, "group": "family",
				     "route": [{"floor": "F_3_2", "x": 3.5, "y": 2.5, "wait": 0.0}, {"floor": "F_5_2", "x": 5.5, "y": 2.5, "wait": 2.0}]},
				    {"name": "family_2", "behaviour": "avoids", "speed": 1.2, "start": 1.0, "loop": false, "group": "family",
				     "route": [{"floor": "F_3_2", "x": 3.5, "y": 2.5, "wait": 0.0}, {"floor": "F_5_2", "x": 5.5, "y": 2.5, "wait": 2.0}]},
				    {"name": "ann", "behaviour": "avoids", "speed": 0.8, "speedTo": 1.0, "start": 0.0, "loop": false,
				     "route": [{"floor": "F_6_3", "x": 6.5, "y": 3.5, "wait": 0.0}]}
				  ]
				}
				""", text.substring(text.indexOf("  \"people\"")));
		JsonNode animation = JSON.readTree(text);
		assertEquals(6, animation.get("people").size(), "valid JSON");
		assertEquals(List.of(), names(animation.get("objects")), "no one on rails");
	}

	/** Each person is a HUMAN body of its statement's type where it stands, in the order of the text. */
	@Test
	void everyPersonIsAHumanBodyWhereItStands() throws Exception {
		generator.generate(TestCases.withCrowds(), out);
		JsonNode objects = JSON.readTree(out.resolve("world.json").toFile()).get("objects");

		List<String> people = new ArrayList<>();
		objects.forEach(o -> {
			if ("HUMAN".equals(o.get("category").asText())) {
				people.add(o.get("name").asText());
			}
		});
		assertEquals(List.of("shoppers_1", "shoppers_2", "shoppers_3", "family_1", "family_2", "ann"), people);
		JsonNode second = named(objects, "shoppers_2");
		assertArrayEquals(new double[] { 0.35, 1.9, 0.85, 0.0 }, doubles(second.get("pose")));
		assertEquals("F_0_1", second.get("floor").asText());
		assertEquals("Human", second.get("type").asText());
		assertArrayEquals(new double[] { 3.5, 2.5, 0.85, 0.0 }, doubles(named(objects, "family_1").get("pose")));
		JsonNode follower = named(objects, "family_2");
		assertArrayEquals(new double[] { 3.5, 1.9, 0.85, 0.0 }, doubles(follower.get("pose")),
				"the nearest point 0.6 m from the leader, the first in lattice order");
		assertEquals("F_3_1", follower.get("floor").asText());
		assertEquals("Adult", named(objects, "ann").get("type").asText());
		NodeList models = DocumentBuilderFactory.newInstance().newDocumentBuilder()
				.parse(out.resolve("world.sdf").toFile()).getElementsByTagName("model");
		List<String> sdf = new ArrayList<>();
		for (int i = 0; i < models.getLength(); i++) {
			sdf.add(((Element) models.item(i)).getAttribute("name"));
		}
		assertEquals(names(objects), sdf);
	}

	/** The validator refuses these; a model built in code gets a generation error instead of people in walls. */
	@Test
	void aCrowdOrGroupThatDoesNotFitIsAnError() {
		TestCase crowded = TestCases.withCrowds();
		((Crowd) crowded.getOwnedEnvironment().getOwnedObjects().get(0)).setCount(4);
		GenerationException e = assertThrows(GenerationException.class, () -> generator.generate(crowded, out));
		assertTrue(e.getMessage().contains("crowd shoppers of 4: its from floors hold 3"), e.getMessage());

		TestCase big = TestCases.withCrowds();
		((Group) big.getOwnedEnvironment().getOwnedObjects().get(1)).setCount(12);
		e = assertThrows(GenerationException.class, () -> generator.generate(big, out));
		assertTrue(e.getMessage().contains("group family of 12: F_3_2 and the free floors beside it hold 8"),
				e.getMessage());
	}

	/** A case without crowds, groups or speed ranges has neither speedTo nor group: its bytes are as before. */
	@Test
	void withoutThemNothingChanges() throws Exception {
		generator.generate(TestCases.withPeople(), out);
		String text = Files.readString(out.resolve("animation.json"));
		assertFalse(text.contains("speedTo"), text);
		assertFalse(text.contains("group"), text);
	}

	private static JsonNode named(JsonNode array, String name) {
		for (JsonNode node : array) {
			if (name.equals(node.get("name").asText())) {
				return node;
			}
		}
		throw new AssertionError("no " + name);
	}

	private static List<String> names(JsonNode array) {
		List<String> names = new ArrayList<>();
		array.forEach(node -> names.add(node.get("name").asText()));
		return names;
	}

	private static double[] doubles(JsonNode array) throws IOException {
		double[] values = new double[array.size()];
		for (int i = 0; i < values.length; i++) {
			values[i] = array.get(i).asDouble();
		}
		return values;
	}
}
