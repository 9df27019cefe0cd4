/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.model;

import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.CatalogueFactory;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.Shape;
import org.rei.catalogue.util.Catalogues;
import org.rei.monitor.config.MonitorSpec;

/**
 * The catalogue of the run as an EMF model: the types monitor.json lists (what the generator used), completed by
 * the default catalogue's types. It lives in the snapshot's resource, so an XMI snapshot is self-contained.
 */
public final class CatalogueBuilder {

	private CatalogueBuilder() {
	}

	public static Catalogue build(MonitorSpec spec) {
		Catalogue catalogue = CatalogueFactory.eINSTANCE.createCatalogue();
		catalogue.setName(spec.testcase() == null ? "run" : spec.testcase());
		for (MonitorSpec.CatalogueEntry e : spec.catalogue()) {
			ObjectType t = CatalogueFactory.eINSTANCE.createObjectType();
			t.setName(e.name());
			t.setCategory(ObjectCategory.get(e.category()));
			t.setShape(Shape.get(e.shape()));
			t.setSizeX(e.size()[0]);
			t.setSizeY(e.size()[1]);
			t.setSizeZ(e.size()[2]);
			t.setMass(e.mass());
			catalogue.getOwnedTypes().add(t);
		}
		Catalogue defaults = Catalogues.loadDefault(new ResourceSetImpl());
		for (ObjectType t : defaults.getOwnedTypes()) {
			if (Catalogues.find(catalogue, t.getName()).isEmpty()) {
				ObjectType copy = CatalogueFactory.eINSTANCE.createObjectType();
				copy.setName(t.getName());
				copy.setCategory(t.getCategory());
				copy.setShape(t.getShape());
				copy.setSizeX(t.getSizeX());
				copy.setSizeY(t.getSizeY());
				copy.setSizeZ(t.getSizeZ());
				copy.setMass(t.getMass());
				catalogue.getOwnedTypes().add(copy);
			}
		}
		return catalogue;
	}

	/**
	 * A POLYGON type's vertices, which monitor.json does not list: its first object's footprint in world.json (the
	 * polygon about the bounding box's centre, counter-clockwise), so the runtime model's furniture has its
	 * polygon for queries over the model; the monitor's distances take the footprint itself.
	 */
	public static void addPolygons(Catalogue catalogue, org.rei.monitor.config.World world) {
		for (org.rei.monitor.config.World.WorldObject o : world.objects()) {
			if (o.footprint() == null || o.footprint().points() == null) {
				continue;
			}
			Catalogues.find(catalogue, o.type()).filter(t -> t.getShape() == Shape.POLYGON && t.getVertices().isEmpty())
					.ifPresent(t -> {
						for (double[] p : o.footprint().points()) {
							org.rei.catalogue.Vertex v = CatalogueFactory.eINSTANCE.createVertex();
							v.setX(p[0]);
							v.setY(p[1]);
							t.getVertices().add(v);
						}
					});
		}
	}
}
