/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.derived;

import org.eclipse.emf.common.notify.Notifier;
import org.eclipse.emf.common.notify.impl.AdapterImpl;

/** Marks model elements that were derived from a compact room description rather than written in the text. */
public final class DerivedMarker extends AdapterImpl {

	private static final DerivedMarker INSTANCE = new DerivedMarker();

	private DerivedMarker() {
	}

	public static <T extends Notifier> T mark(T element) {
		element.eAdapters().add(INSTANCE);
		return element;
	}

	public static boolean isDerived(Notifier element) {
		return element.eAdapters().contains(INSTANCE);
	}

	@Override
	public boolean isAdapterForType(Object type) {
		return type == DerivedMarker.class;
	}
}
