/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.validation.AbstractDeclarativeValidator;
import org.eclipse.xtext.validation.EValidatorRegistrar;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.dsl.derived.DerivedMarker;

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
