/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.documentation;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.resource.DefaultLocationInFileProvider;
import org.eclipse.xtext.util.ITextRegion;
import org.rei.context.MonitorSpec;

/**
 * The monitor block has no name, so its significant region would be its first keyword only: a hover on
 * {@code close 0.25} would show nothing. The whole block is its significant region.
 */
public class ReiLocationInFileProvider extends DefaultLocationInFileProvider {

	@Override
	public ITextRegion getSignificantTextRegion(EObject obj) {
		return obj instanceof MonitorSpec ? getFullTextRegion(obj) : super.getSignificantTextRegion(obj);
	}
}
