/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.derived;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.resource.DerivedStateAwareResource;
import org.eclipse.xtext.resource.IDerivedStateComputer;
import org.rei.context.Environment;
import org.rei.context.TestCase;

/**
 * Installs the floors and walls of rooms written in a compact form (a grid size or a map) into the model,
 * and removes them again before the text is re-parsed.
 */
public class RoomDerivedStateComputer implements IDerivedStateComputer {

	@Override
	public void installDerivedState(DerivedStateAwareResource resource, boolean preIndexingPhase) {
		Environment environment = environmentOf(resource);
		if (environment != null && environment.getOwnedLayout() != null) {
			environment.getOwnedBlocks().addAll(RoomDesugaring.blocksOf(environment.getOwnedLayout()));
		}
	}

	@Override
	public void discardDerivedState(DerivedStateAwareResource resource) {
		Environment environment = environmentOf(resource);
		if (environment != null) {
			environment.getOwnedBlocks().removeIf(DerivedMarker::isDerived);
		}
	}

	private static Environment environmentOf(DerivedStateAwareResource resource) {
		if (resource.getContents().isEmpty()) {
			return null;
		}
		EObject root = resource.getContents().get(0);
		return root instanceof TestCase testCase ? testCase.getOwnedEnvironment() : null;
	}
}
