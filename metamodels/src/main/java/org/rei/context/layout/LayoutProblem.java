/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.context.layout;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;

/**
 * Why a room cannot be laid out. Carries the element and, where one is to blame, the neighbour reference, so that
 * an editor can mark the source position.
 *
 * @param element the floor or wall at fault
 * @param feature the neighbour reference at fault, or {@code null} for the element as a whole
 * @param code one of {@link LayoutIssueCodes}
 * @param message human-readable explanation naming the elements and cells involved
 */
public record LayoutProblem(EObject element, EStructuralFeature feature, String code, String message) {

	@Override
	public String toString() {
		return code + ": " + message;
	}
}
