/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.rei.vepl.conversion.VeplValueConverters;
import org.rei.vepl.documentation.VeplDocumentationProvider;

/** Bindings of the VEPL runtime beyond the generated defaults. */
public class VeplRuntimeModule extends AbstractVeplRuntimeModule {

	@Override
	public Class<? extends IValueConverterService> bindIValueConverterService() {
		return VeplValueConverters.class;
	}

	/** Hovers in editors (the language server asks it). */
	public Class<? extends IEObjectDocumentationProvider> bindIEObjectDocumentationProvider() {
		return VeplDocumentationProvider.class;
	}
}
