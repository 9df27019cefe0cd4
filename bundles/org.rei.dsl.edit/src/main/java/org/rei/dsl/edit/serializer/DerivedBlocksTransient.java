/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.serializer;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.serializer.sequencer.LegacyTransientValueService;
import org.rei.context.ContextPackage;
import org.rei.dsl.derived.DerivedMarker;

/**
 * The blocks of a grid or map room live in the model (derived state) but not in the text: if a whole room is ever
 * serialized, they must not come out as thousands of explicit floor statements.
 */
public class DerivedBlocksTransient extends LegacyTransientValueService {

	@Override
	public ListTransient isListTransient(EObject owner, EStructuralFeature feature) {
		if (feature == ContextPackage.Literals.ENVIRONMENT__OWNED_BLOCKS
				&& ((List<?>) owner.eGet(feature)).stream().anyMatch(b -> DerivedMarker.isDerived((EObject) b))) {
			return ListTransient.SOME;
		}
		return super.isListTransient(owner, feature);
	}

	@Override
	public boolean isValueInListTransient(EObject owner, int index, EStructuralFeature feature) {
		if (feature == ContextPackage.Literals.ENVIRONMENT__OWNED_BLOCKS) {
			return DerivedMarker.isDerived((EObject) ((List<?>) owner.eGet(feature)).get(index));
		}
		return super.isValueInListTransient(owner, index, feature);
	}
}
