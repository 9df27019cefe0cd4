/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.parser.IParser;
import org.eclipse.xtext.validation.IResourceValidator;
import org.rei.vepl.conversion.VeplValueConverters;
import org.rei.vepl.documentation.VeplDocumentationProvider;
import org.rei.vepl.parser.VeplGuardedParser;
import org.rei.vepl.validation.VeplResourceValidator;

/** Bindings of the VEPL runtime beyond the generated defaults. */
public class VeplRuntimeModule extends AbstractVeplRuntimeModule {

	@Override
	public Class<? extends IValueConverterService> bindIValueConverterService() {
		return VeplValueConverters.class;
	}

	/** Refuses brackets nested too deep before ANTLR's parser recurses into them; never throws. */
	@Override
	public Class<? extends IParser> bindIParser() {
		return VeplGuardedParser.class;
	}

	/** Every check, those on the whole file too, for the loader and the language server alike. */
	public Class<? extends IResourceValidator> bindIResourceValidator() {
		return VeplResourceValidator.class;
	}

	/** Hovers in editors (the language server asks it). */
	public Class<? extends IEObjectDocumentationProvider> bindIEObjectDocumentationProvider() {
		return VeplDocumentationProvider.class;
	}
}
