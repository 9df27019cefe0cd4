/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.scoping;

import java.util.stream.Collectors;
import java.util.stream.StreamSupport;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.eclipse.xtext.scoping.IScope;
import org.rei.catalogue.CataloguePackage;
import org.rei.context.ContextPackage;

import com.google.inject.Inject;

import org.eclipse.xtext.scoping.IScopeProvider;

/** Says what kind of name was expected where a reference does not resolve, and lists candidates when few. */
public class ReiLinkingDiagnosticMessageProvider extends LinkingDiagnosticMessageProvider {

	private static final int MAX_LISTED = 8;

	@Inject
	private IScopeProvider scopeProvider;

	@Override
	public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
		EClass target = context.getReference().getEReferenceType();
		String what = describe(target);
		String message = "Unknown " + what + " '" + context.getLinkText() + "': expected the name of "
				+ article(what) + " " + what + candidates(context);
		return new DiagnosticMessage(message, Severity.ERROR, Diagnostic.LINKING_DIAGNOSTIC);
	}

	private String candidates(ILinkingDiagnosticContext context) {
		IScope scope = scopeProvider.getScope(context.getContext(), context.getReference());
		var names = StreamSupport.stream(scope.getAllElements().spliterator(), false)
				.map(d -> d.getName().toString()).limit(MAX_LISTED + 1L).toList();
		if (names.isEmpty()) {
			return "";
		}
		String listed = names.stream().limit(MAX_LISTED).collect(Collectors.joining(", "));
		return " (" + listed + (names.size() > MAX_LISTED ? ", ..." : "") + ")";
	}

	private static String describe(EClass target) {
		if (target == ContextPackage.Literals.FLOOR) {
			return "floor";
		}
		if (target == ContextPackage.Literals.BUILDING_BLOCK) {
			return "floor or wall";
		}
		if (target == CataloguePackage.Literals.OBJECT_TYPE) {
			return "object type";
		}
		return target.getName();
	}

	private static String article(String noun) {
		return "aeiou".indexOf(noun.charAt(0)) >= 0 ? "an" : "a";
	}
}
