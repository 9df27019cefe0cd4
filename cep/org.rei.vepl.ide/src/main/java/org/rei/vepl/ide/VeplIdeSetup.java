/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.ide;

import org.eclipse.xtext.util.Modules2;
import org.rei.vepl.VeplRuntimeModule;
import org.rei.vepl.VeplStandaloneSetup;

import com.google.inject.Guice;
import com.google.inject.Injector;

/** The VEPL language with its editor services: what the language server registers for {@code .vepl}. */
public class VeplIdeSetup extends VeplStandaloneSetup {

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new VeplRuntimeModule(), new VeplIdeModule()));
	}
}
