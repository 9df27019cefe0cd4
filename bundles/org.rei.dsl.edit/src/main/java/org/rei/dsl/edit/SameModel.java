/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.util.EcoreUtil;

/**
 * EMF's structural equality, with cross references compared through a pairing of the two containment trees made
 * beforehand: EqualityHelper itself follows a chain of neighbour references one stack frame per floor, which
 * overflows in a 200 x 200 room. Targets outside the trees (catalogue types) are compared by URI.
 */
final class SameModel extends EcoreUtil.EqualityHelper {

	private static final long serialVersionUID = 1L;

	private final Map<EObject, EObject> pairs = new IdentityHashMap<>();
	private final Set<EObject> paired = Collections.newSetFromMap(new IdentityHashMap<>());

	static boolean equal(EObject a, EObject b) {
		SameModel helper = new SameModel();
		helper.pair(a, b);
		Iterator<EObject> first = a.eAllContents();
		Iterator<EObject> second = b.eAllContents();
		while (first.hasNext() && second.hasNext()) {
			helper.pair(first.next(), second.next());
		}
		return !first.hasNext() && !second.hasNext() && helper.equals(a, b);
	}

	private void pair(EObject first, EObject second) {
		pairs.put(first, second);
		paired.add(second);
	}

	@Override
	protected boolean haveEqualReference(EObject a, EObject b, EReference reference) {
		if (reference.isContainment() || reference.isContainer()) {
			return super.haveEqualReference(a, b, reference);
		}
		Object first = a.eGet(reference);
		Object second = b.eGet(reference);
		if (!reference.isMany()) {
			return corresponds(first, second);
		}
		List<?> firstList = (List<?>) first;
		List<?> secondList = (List<?>) second;
		if (firstList.size() != secondList.size()) {
			return false;
		}
		for (int i = 0; i < firstList.size(); i++) {
			if (!corresponds(firstList.get(i), secondList.get(i))) {
				return false;
			}
		}
		return true;
	}

	private boolean corresponds(Object first, Object second) {
		if (first == null || second == null) {
			return first == second;
		}
		EObject partner = pairs.get(first);
		if (partner != null) {
			return partner == second;
		}
		return !paired.contains(second)
				&& Objects.equals(EcoreUtil.getURI((EObject) first), EcoreUtil.getURI((EObject) second));
	}
}
