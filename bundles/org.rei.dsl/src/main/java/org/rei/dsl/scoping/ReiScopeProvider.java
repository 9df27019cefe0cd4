/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.scoping;

import java.util.List;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.Scopes;
import org.eclipse.xtext.scoping.impl.MapBasedScope;
import org.eclipse.xtext.util.IResourceScopeCache;
import org.eclipse.xtext.util.Tuples;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.CataloguePackage;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.context.TestCase;
import org.rei.dsl.catalogue.CatalogueImports;

import com.google.inject.Inject;

/**
 * Floors and walls are found by their simple name anywhere in the test case (the mission names floors of the
 * room); object types come from the catalogues the test case imports, then the default one. Scopes are hashed and cached per resource, because a generated
 * room may have ten thousand floors and as many references to them.
 */
public class ReiScopeProvider extends AbstractReiScopeProvider {

	@Inject
	private IResourceScopeCache cache;

	@Override
	public IScope getScope(EObject context, EReference reference) {
		EClass target = reference.getEReferenceType();
		Resource resource = context.eResource();
		if (resource != null && ContextPackage.Literals.BUILDING_BLOCK.isSuperTypeOf(target)) {
			return cache.get(Tuples.create(ReiScopeProvider.class, target), resource,
					() -> blocksScope(context, target));
		}
		if (resource != null && CataloguePackage.Literals.OBJECT_TYPE.isSuperTypeOf(target)) {
			return cache.get(ReiScopeProvider.class, resource, () -> typesScope(context, resource));
		}
		return super.getScope(context, reference);
	}

	/** The imported catalogues' types first, in import order, then the default catalogue's. */
	private static IScope typesScope(EObject context, Resource resource) {
		IScope scope = MapBasedScope.createScope(IScope.NULLSCOPE,
				Scopes.scopedElementsFor(Catalogues.loadDefault(resource.getResourceSet()).getOwnedTypes()));
		TestCase testCase = EcoreUtil2.getContainerOfType(context, TestCase.class);
		if (testCase != null) {
			List<Catalogue> imported = CatalogueImports.catalogues(testCase);
			for (int i = imported.size() - 1; i >= 0; i--) {
				scope = MapBasedScope.createScope(scope, Scopes.scopedElementsFor(imported.get(i).getOwnedTypes()));
			}
		}
		return scope;
	}

	private static IScope blocksScope(EObject context, EClass target) {
		TestCase testCase = EcoreUtil2.getContainerOfType(context, TestCase.class);
		Environment environment = testCase == null ? null : testCase.getOwnedEnvironment();
		if (environment == null) {
			return IScope.NULLSCOPE;
		}
		List<EObject> blocks = environment.getOwnedBlocks().stream().filter(target::isInstance)
				.map(EObject.class::cast).toList();
		return MapBasedScope.createScope(IScope.NULLSCOPE, Scopes.scopedElementsFor(blocks));
	}
}
