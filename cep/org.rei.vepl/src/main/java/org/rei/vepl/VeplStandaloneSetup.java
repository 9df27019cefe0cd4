/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl;

import com.google.inject.Injector;

/** Sets the language up without Equinox: the compiler, the monitor, the Maven build and tests use it. */
public class VeplStandaloneSetup extends VeplStandaloneSetupGenerated {

	public static Injector doSetup() {
		return new VeplStandaloneSetup().createInjectorAndDoEMFRegistration();
	}
}
