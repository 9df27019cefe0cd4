/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.serializer;

import org.eclipse.emf.ecore.EStructuralFeature;

/**
 * More than one element would be written at one place of a list: Xtext's diff builder merges such insertions with
 * every rewrite that follows them. The caller splits its change into smaller ones.
 */
public class TangledListException extends RuntimeException {

	private static final long serialVersionUID = 1L;

	public TangledListException(EStructuralFeature feature) {
		super("several elements would be written at one place of '" + feature.getName() + "'");
	}
}
