/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.engine;

import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

import org.drools.base.base.ClassObjectType;
import org.drools.core.impl.InternalRuleBase;
import org.drools.core.reteoo.ObjectTypeNode;
import org.eclipse.emf.common.notify.Notification;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.util.EContentAdapter;
import org.kie.api.runtime.KieSession;
import org.kie.api.runtime.rule.FactHandle;

/**
 * The runtime model as Drools facts, so that queries match the EMF model itself (thesis 5.1.5-5.1.6): every object
 * of the model's containment tree is a fact. EMF notifications only mark what changed; {@link #flush()} updates
 * each marked fact once, before the engine fires, so a query sees a step's changes together and a pose that changes
 * in four attributes is one update. Objects added to the tree become facts, removed ones stop being facts.
 *
 * <p>A change inside a value object (an object with attributes only, held by a single containment: a
 * {@code Pose}, a {@code Twist}) also updates its container, so a pattern on {@code ConcreteObject(pose.x > 3)}
 * follows the pose. References are not followed: a pattern joins the object it needs instead of reading through a
 * reference ({@code RobotDescription(body == $o)}, not {@code body.pose.x}).
 *
 * <p>Only objects of a class some loaded pattern or query matches are facts (the session's object type nodes say
 * which): the model costs nothing per step when no query reads it, and the moving bodies cost their updates only
 * when a query reads bodies.
 */
final class ModelFacts extends EContentAdapter {

	private final KieSession session;
	private final Set<Class<?>> matched;
	private final Map<Class<?>, Boolean> relevant = new HashMap<>();
	private final Map<EObject, FactHandle> handles = new IdentityHashMap<>();
	// insertion order, so that updates (and the query events they cause) come in the same order every run
	private final Set<EObject> dirty = new LinkedHashSet<>();

	private ModelFacts(KieSession session, Set<Class<?>> matched) {
		this.session = session;
		this.matched = matched;
	}

	/** The model's objects as facts of the session, or null when no pattern of it matches any of them. */
	static ModelFacts attach(KieSession session, EObject root) {
		Set<Class<?>> matched = new HashSet<>();
		for (ObjectTypeNode node : ((InternalRuleBase) session.getKieBase()).getRete().getObjectTypeNodes()) {
			if (node.getObjectType() instanceof ClassObjectType type && type.getClassType() != Object.class
					&& EObject.class.isAssignableFrom(type.getClassType())) {
				matched.add(type.getClassType());
			}
		}
		if (matched.isEmpty()) {
			return null;
		}
		ModelFacts facts = new ModelFacts(session, matched);
		facts.insertTree(root);
		root.eAdapters().add(facts);
		return facts;
	}

	private boolean isFact(EObject o) {
		return relevant.computeIfAbsent(o.getClass(), c -> matched.stream().anyMatch(t -> t.isAssignableFrom(c)));
	}

	int size() {
		return handles.size();
	}

	@Override
	public void notifyChanged(Notification n) {
		super.notifyChanged(n); // keeps this adapter on added contents
		if (n.isTouch() || !(n.getNotifier() instanceof EObject changed)) {
			return;
		}
		if (n.getFeature() instanceof EReference r && r.isContainment()) {
			switch (n.getEventType()) {
			case Notification.SET, Notification.UNSET -> {
				deleteTree(n.getOldValue());
				insertTree(n.getNewValue());
			}
			case Notification.ADD -> insertTree(n.getNewValue());
			case Notification.ADD_MANY -> ((Iterable<?>) n.getNewValue()).forEach(this::insertTree);
			case Notification.REMOVE -> deleteTree(n.getOldValue());
			case Notification.REMOVE_MANY -> ((Iterable<?>) n.getOldValue()).forEach(this::deleteTree);
			default -> {
				// MOVE: the same objects in another order
			}
			}
		}
		if (handles.containsKey(changed)) {
			dirty.add(changed);
		}
		EObject container = changed.eContainer();
		if (container != null && isValue(changed) && handles.containsKey(container)) {
			dirty.add(container);
		}
	}

	/** Updates every fact that changed since the last flush. */
	void flush() {
		if (dirty.isEmpty()) {
			return;
		}
		for (EObject o : dirty) {
			FactHandle handle = handles.get(o);
			if (handle != null) {
				session.update(handle, o);
			}
		}
		dirty.clear();
	}

	private static boolean isValue(EObject o) {
		EReference containment = o.eContainmentFeature();
		return containment != null && !containment.isMany() && o.eClass().getEAllReferences().isEmpty();
	}

	private void insertTree(Object value) {
		if (value instanceof EObject o && !handles.containsKey(o)) {
			if (isFact(o)) {
				handles.put(o, session.insert(o));
			}
			o.eContents().forEach(this::insertTree);
		}
	}

	private void deleteTree(Object value) {
		if (value instanceof EObject o) {
			FactHandle handle = handles.remove(o);
			if (handle != null) {
				session.delete(handle);
			}
			dirty.remove(o);
			o.eContents().forEach(this::deleteTree);
		}
	}
}
