/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import org.eclipse.xtext.util.Modules2;
import org.rei.dsl.ReiRuntimeModule;
import org.rei.dsl.ReiStandaloneSetup;
import org.rei.dsl.edit.serializer.RoomEditModule;

import com.google.inject.Guice;
import com.google.inject.Injector;

/**
 * The language with the change serializer's services (formatter, partial serializer) added, set up once per JVM
 * like {@code ReiIdeSetup}: resources that documents create come from this injector, so the serializer finds its
 * services through them.
 */
public class RoomEditSetup extends ReiStandaloneSetup {

	private static Injector injector;

	/** The shared injector, created (and the language registered) on first use. */
	public static synchronized Injector injector() {
		if (injector == null) {
			injector = new RoomEditSetup().createInjectorAndDoEMFRegistration();
		}
		return injector;
	}

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new ReiRuntimeModule(), new RoomEditModule()));
	}
}
