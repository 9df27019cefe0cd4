/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.ide;

/** Bindings of VEPL's editor services beyond the generated defaults (none yet). */
public class VeplIdeModule extends AbstractVeplIdeModule {
}
