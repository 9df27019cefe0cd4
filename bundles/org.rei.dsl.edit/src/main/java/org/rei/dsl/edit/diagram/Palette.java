/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.diagram;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.context.ContextPackage;
import org.rei.context.TestCase;

/**
 * The catalogue types a test case can name: the scope its type references are linked in, so the palette offers
 * exactly what the text can use - the imported catalogues' types in import order, then the default catalogue's
 * that no imported type of the same name hides.
 */
public final class Palette {

	private Palette() {
	}

	public static List<PaletteType> of(TestCase testCase, IScopeProvider scopes) {
		List<PaletteType> types = new ArrayList<>();
		if (testCase == null || testCase.eResource() == null) {
			return types;
		}
		for (IEObjectDescription description : scopes
				.getScope(testCase, ContextPackage.Literals.SIMULATION_OBJECT__TYPE).getAllElements()) {
			EObject resolved = EcoreUtil.resolve(description.getEObjectOrProxy(), testCase);
			if (resolved instanceof ObjectType type && !type.eIsProxy() && type.getName() != null) {
				double[] size = { type.getSizeX(), type.getSizeY() };
				if (org.rei.catalogue.util.Polygons.isPolygon(type) && !type.getVertices().isEmpty()) {
					double[] b = org.rei.catalogue.util.Polygons.bounds(org.rei.catalogue.util.Polygons.points(type));
					size = new double[] { b[2] - b[0], b[3] - b[1] }; // a polygon's bounding box
				}
				types.add(new PaletteType(type.getName(), category(type.getCategory()),
						type.getShape() == null ? null : type.getShape().getLiteral().toLowerCase(), size[0], size[1],
						type.getColour()));
			}
		}
		return types;
	}

	/** The keyword a catalogue declares the category with ({@code type Sofa : object ...}, {@code robot type}). */
	static String category(ObjectCategory category) {
		if (category == null) {
			return null;
		}
		switch (category) {
		case FLOOR:
			return "floor";
		case WALL:
			return "wall";
		case STATIC:
			return "object";
		case DYNAMIC:
			return "dynamic";
		case HUMAN:
			return "human";
		case ROBOT:
			return "robot";
		default:
			return category.getLiteral().toLowerCase();
		}
	}
}
