/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.validation.CompositeEValidator;

import com.google.inject.Binder;
import com.google.inject.name.Names;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.eclipse.xtext.resource.DerivedStateAwareResource;
import org.eclipse.xtext.resource.DerivedStateAwareResourceDescriptionManager;
import org.eclipse.xtext.resource.IDerivedStateComputer;
import org.eclipse.xtext.resource.ILocationInFileProvider;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.XtextResource;
import org.rei.dsl.conversion.ReiValueConverters;
import org.rei.dsl.derived.RoomDerivedStateComputer;
import org.rei.dsl.documentation.ReiDocumentationProvider;
import org.rei.dsl.documentation.ReiLocationInFileProvider;
import org.rei.dsl.parser.ReiSyntaxErrorMessageProvider;
import org.rei.dsl.scoping.ReiLinkingDiagnosticMessageProvider;

/** Guice bindings of the REI language (runtime, standalone and language server alike). */
public class ReiRuntimeModule extends AbstractReiRuntimeModule {

	@Override
	public Class<? extends IValueConverterService> bindIValueConverterService() {
		return ReiValueConverters.class;
	}

	// Rooms written as a grid or a map get their floors and walls as derived state, so that references
	// like "on F_3_1" link to real model elements and the generators see one uniform floor graph.
	@Override
	public Class<? extends XtextResource> bindXtextResource() {
		return DerivedStateAwareResource.class;
	}

	public Class<? extends IDerivedStateComputer> bindIDerivedStateComputer() {
		return RoomDerivedStateComputer.class;
	}

	public Class<? extends IResourceDescription.Manager> bindIResourceDescription$Manager() {
		return DerivedStateAwareResourceDescriptionManager.class;
	}

	// Linking errors already say which reference is unresolved; EMF's generic proxy check would repeat them.
	public void configureUseEObjectValidator(Binder binder) {
		binder.bindConstant().annotatedWith(Names.named(CompositeEValidator.USE_EOBJECT_VALIDATOR)).to(false);
	}

	// A unit after a number, a part of the test case out of its place: said so, not as an unexpected token.
	public Class<? extends ISyntaxErrorMessageProvider> bindISyntaxErrorMessageProvider() {
		return ReiSyntaxErrorMessageProvider.class;
	}

	public Class<? extends ILinkingDiagnosticMessageProvider> bindILinkingDiagnosticMessageProvider() {
		return ReiLinkingDiagnosticMessageProvider.class;
	}

	// What an editor's hover shows: floors' places, object types' sizes and masses, the thresholds' meaning.
	public Class<? extends IEObjectDocumentationProvider> bindIEObjectDocumentationProvider() {
		return ReiDocumentationProvider.class;
	}

	public Class<? extends ILocationInFileProvider> bindILocationInFileProvider() {
		return ReiLocationInFileProvider.class;
	}
}
