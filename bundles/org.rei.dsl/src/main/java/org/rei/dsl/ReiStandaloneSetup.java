/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl;

import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceFactoryImpl;
import org.rei.catalogue.CataloguePackage;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.ContextPackage;

import com.google.inject.Injector;

/** Sets the language up without Equinox: the CLI, the Maven plugin, the language server and tests use it. */
public class ReiStandaloneSetup extends ReiStandaloneSetupGenerated {

	public static Injector doSetup() {
		return new ReiStandaloneSetup().createInjectorAndDoEMFRegistration();
	}

	@Override
	public void register(Injector injector) {
		// The grammar imports these metamodels instead of generating its own; outside Eclipse nobody else
		// registers them.
		EPackage.Registry.INSTANCE.putIfAbsent(ContextPackage.eNS_URI, ContextPackage.eINSTANCE);
		EPackage.Registry.INSTANCE.putIfAbsent(CataloguePackage.eNS_URI, CataloguePackage.eINSTANCE);
		Resource.Factory.Registry.INSTANCE.getExtensionToFactoryMap().putIfAbsent(Catalogues.EXTENSION,
				new XMIResourceFactoryImpl());
		super.register(injector);
	}
}
