/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.scoping;

/** Default scoping: events and signals are found by simple name in the file and the other loaded files. */
public class VeplScopeProvider extends AbstractVeplScopeProvider {
}
