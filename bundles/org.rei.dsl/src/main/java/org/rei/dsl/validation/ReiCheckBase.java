/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.validation.AbstractDeclarativeValidator;
import org.eclipse.xtext.validation.EValidatorRegistrar;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.context.layout.FloorLayout;
import org.rei.dsl.derived.DerivedMarker;
import org.rei.dsl.derived.RoomDesugaring;

/** Common base of the composed validators: they are registered through {@link ReiValidator} only. */
abstract class ReiCheckBase extends AbstractDeclarativeValidator {

	@Override
	protected List<EPackage> getEPackages() {
		return List.of(ContextPackage.eINSTANCE);
	}

	@Override
	public void register(EValidatorRegistrar registrar) {
		// composed into ReiValidator; registering here too would run every check twice
	}

	/** The room's layout, computed once per validation of the room (a map room's costs) for every validator. */
	protected FloorLayout roomLayout(Environment env) {
		return perRoom("layout", env, () -> RoomDesugaring.layoutOf(env));
	}

	/**
	 * What {@code compute} gives for the room, computed once per validation (the validators share the validation's
	 * context); without a context, computed each time.
	 */
	@SuppressWarnings("unchecked")
	protected <T> T perRoom(String what, Environment env, Supplier<T> compute) {
		Map<Object, Object> context = getContext();
		RoomKey key = new RoomKey(what, env);
		T cached = context == null ? null : (T) context.get(key);
		if (cached == null) {
			cached = compute.get();
			if (context != null) {
				context.put(key, cached);
			}
		}
		return cached;
	}

	/** The default catalogue's Human, the type of a person that names none ({@code null} outside a resource set). */
	protected static ObjectType defaultHuman(EObject element) {
		return element.eResource() == null || element.eResource().getResourceSet() == null ? null
				: Catalogues.find(Catalogues.loadDefault(element.eResource().getResourceSet()), "Human").orElse(null);
	}

	/** A validation context's key of what is computed once per room: what it is, and the room by identity. */
	private record RoomKey(String what, Environment environment) {
		@Override
		public boolean equals(Object other) {
			return other instanceof RoomKey key && key.what.equals(what) && key.environment == environment;
		}

		@Override
		public int hashCode() {
			return 31 * what.hashCode() + System.identityHashCode(environment);
		}
	}

	/**
	 * Reports an error; elements derived from a grid or map have no text of their own, so their problems are
	 * reported on the layout they came from.
	 */
	protected void errorAt(EObject element, EStructuralFeature feature, String message, String code) {
		if (DerivedMarker.isDerived(element) && element.eContainer() instanceof Environment environment) {
			error(message, environment, ContextPackage.Literals.ENVIRONMENT__OWNED_LAYOUT, code);
		} else {
			error(message, element, feature, code);
		}
	}
}
