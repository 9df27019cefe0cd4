/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.serializer;

import java.util.List;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.ide.serializer.hooks.IEObjectDescriptionProvider;
import org.eclipse.xtext.resource.IEObjectDescription;

/**
 * The change serializer indexes every element's name before and after a change to find the references a rename
 * must update. The room editor renames nothing (and turns reference updating off), so it skips the index: in a room
 * of ten thousand floors that was a tenth of an edit's time.
 */
public class NoNameIndex implements IEObjectDescriptionProvider {

	@Override
	public Iterable<IEObjectDescription> getEObjectDescriptions(Resource resource) {
		return List.of();
	}
}
