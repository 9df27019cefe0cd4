/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.serializer;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.change.FeatureChange;
import org.eclipse.emf.ecore.change.ListChange;
import org.eclipse.xtext.AbstractElement;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Group;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ParserRule;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.UnorderedGroup;
import org.eclipse.xtext.formatting2.regionaccess.IEObjectRegion;
import org.eclipse.xtext.formatting2.regionaccess.IHiddenRegion;
import org.eclipse.xtext.formatting2.regionaccess.ISemanticRegion;
import org.eclipse.xtext.formatting2.regionaccess.ITextRegionAccess;
import org.eclipse.xtext.ide.serializer.impl.PartialSerializer;
import org.eclipse.xtext.serializer.ISerializationContext;
import org.eclipse.xtext.serializer.analysis.IGrammarConstraintProvider.IConstraint;
import org.eclipse.xtext.serializer.analysis.IGrammarConstraintProvider.IConstraintElement;
import org.eclipse.xtext.serializer.diagnostic.ISerializationDiagnostic;
import org.eclipse.xtext.serializer.tokens.ICrossReferenceSerializer;
import org.eclipse.xtext.serializer.tokens.IValueSerializer;

import org.rei.dsl.derived.DerivedMarker;

import com.google.inject.Inject;

/**
 * Xtext's partial serializer with three gaps closed that the REI grammar runs into; without them a small edit
 * re-serializes a whole room (derived floors included) or leaves a keyword without its value.
 * <ul>
 * <li>A list inside a repeated group of alternatives ({@code (ownedBlocks+=.. | ownedObjects+=.. | ..)*}) is not
 * "many" to the constraint analysis (its assignments are each optional, not repeated), so adding or deleting one object fell back to the enclosing room: here list
 * changes are turned into region deletions and insertions whenever the feature itself is many.</li>
 * <li>Unsetting an optional {@code 'yaw' yaw=Number} deleted "90" and kept "yaw": the keyword goes with it.</li>
 * <li>Setting such a value where the text has none re-serialized the whole statement: a trailing optional group
 * is appended after the statement's last token instead, so the rest of the line keeps its text.</li>
 * </ul>
 */
public class RoomPartialSerializer extends PartialSerializer {

	@Inject
	private IValueSerializer valueSerializer;

	@Inject
	private ICrossReferenceSerializer crossReferenceSerializer;

	private final ISerializationDiagnostic.Acceptor errors = ISerializationDiagnostic.EXCEPTION_THROWING_ACCEPTOR;

	@Override
	protected List<SerializationStrategy> trySerializeMultiValue(EObject owner, FeatureChange change,
			IEObjectRegion ownerRegion, IConstraint constraint) {
		EStructuralFeature feature = change.getFeature();
		List<IConstraintElement> assignments = constraint.getFeatures()[owner.eClass().getFeatureID(feature)]
				.getAssignments();
		boolean repeatedGroup = !assignments.isEmpty() && assignments.stream().noneMatch(IConstraintElement::isMany);
		if (repeatedGroup && feature instanceof EReference reference && reference.isContainment()) {
			return serializeContainmentList(owner, reference, change, ownerRegion);
		}
		return super.trySerializeMultiValue(owner, change, ownerRegion, constraint);
	}

	/**
	 * Old list = the elements with a region in the original text (in text order), new list = the feature's value.
	 * Deleted elements lose their region; the longest run of elements that kept their order stays put; the others
	 * (new or moved) are written next to their nearest stable neighbour, moved ones with their original text.
	 */
	private List<SerializationStrategy> serializeContainmentList(EObject owner, EReference feature,
			FeatureChange change, IEObjectRegion ownerRegion) {
		ITextRegionAccess access = ownerRegion.getTextRegionAccess();
		Set<EObject> candidates = new HashSet<>();
		for (ListChange listChange : change.getListChanges()) {
			candidates.addAll(listChange.getReferenceValues());
		}
		List<?> current = (List<?>) owner.eGet(feature);
		for (Object value : current) {
			candidates.add((EObject) value);
		}
		List<IEObjectRegion> old = new ArrayList<>();
		for (EObject candidate : candidates) {
			IEObjectRegion region = access.regionForEObject(candidate);
			if (region != null) {
				old.add(region);
			}
		}
		old.sort(Comparator.comparingInt(IEObjectRegion::getOffset));
		Map<EObject, Integer> oldIndex = new HashMap<>();
		for (int i = 0; i < old.size(); i++) {
			oldIndex.put(old.get(i).getSemanticElement(), i);
		}
		// elements derived from a compact room description have no text and are never written
		List<EObject> now = new ArrayList<>();
		for (Object value : current) {
			EObject element = (EObject) value;
			if (oldIndex.containsKey(element) || !DerivedMarker.isDerived(element)) {
				now.add(element);
			}
		}
		Set<EObject> stable = longestOrderedRun(now, oldIndex);
		List<SerializationStrategy> result = new ArrayList<>();
		for (IEObjectRegion region : old) {
			EObject element = region.getSemanticElement();
			if (!stable.contains(element)) {
				result.add(new DeleteRegionStrategy(region));
			}
		}
		for (int i = 0; i < now.size(); i++) {
			EObject element = now.get(i);
			if (stable.contains(element)) {
				continue;
			}
			IHiddenRegion insertAt = insertionPoint(now, i, stable, access, ownerRegion);
			if (insertAt == null) {
				return null;
			}
			IEObjectRegion original = access.regionForEObject(element);
			if (original != null) {
				result.add(new InsertRegionStrategy(insertAt, original));
			} else {
				ISerializationContext context = getSerializationContext(element);
				result.add(new SerializeRecursiveStrategy(insertAt, element, context));
			}
		}
		return result;
	}

	/** After the closest stable element before it, else before the closest one after it, else before the '}'. */
	private static IHiddenRegion insertionPoint(List<EObject> now, int index, Set<EObject> stable,
			ITextRegionAccess access, IEObjectRegion ownerRegion) {
		for (int j = index - 1; j >= 0; j--) {
			if (stable.contains(now.get(j))) {
				return access.regionForEObject(now.get(j)).getNextHiddenRegion();
			}
		}
		for (int j = index + 1; j < now.size(); j++) {
			if (stable.contains(now.get(j))) {
				return access.regionForEObject(now.get(j)).getPreviousHiddenRegion();
			}
		}
		List<ISemanticRegion> closing = ownerRegion.getRegionFor().keywords("}");
		return closing.isEmpty() ? null : closing.get(closing.size() - 1).getPreviousHiddenRegion();
	}

	/** The longest subsequence of {@code now} whose old indices increase: those elements need no edit. */
	private static Set<EObject> longestOrderedRun(List<EObject> now, Map<EObject, Integer> oldIndex) {
		List<EObject> kept = now.stream().filter(oldIndex::containsKey).toList();
		int n = kept.size();
		int[] length = new int[n];
		int[] previous = new int[n];
		int best = -1;
		for (int i = 0; i < n; i++) {
			length[i] = 1;
			previous[i] = -1;
			for (int j = 0; j < i; j++) {
				if (oldIndex.get(kept.get(j)) < oldIndex.get(kept.get(i)) && length[j] + 1 > length[i]) {
					length[i] = length[j] + 1;
					previous[i] = j;
				}
			}
			if (best < 0 || length[i] > length[best]) {
				best = i;
			}
		}
		Set<EObject> result = new HashSet<>();
		for (int i = best; i >= 0; i = previous[i]) {
			result.add(kept.get(i));
		}
		return result;
	}

	@Override
	protected List<SerializationStrategy> trySerializeSingleValue(EObject owner, FeatureChange change,
			IEObjectRegion ownerRegion, IConstraint constraint) {
		EStructuralFeature feature = change.getFeature();
		boolean containment = feature instanceof EReference reference && reference.isContainment();
		List<IConstraintElement> assignments = constraint.getFeatures()[owner.eClass().getFeatureID(feature)]
				.getAssignments();
		if (containment || assignments.size() != 1) {
			return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
		}
		Assignment assignment = GrammarUtil.containingAssignment(assignments.get(0).getGrammarElement());
		Keyword keyword = leadingKeyword(assignment);
		ISemanticRegion value = ownerRegion.getRegionFor().feature(feature);
		if (keyword == null) {
			return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
		}
		if (!owner.eIsSet(feature) && value != null) {
			ISemanticRegion first = value.getPreviousSemanticRegion();
			if (first == null || first.getGrammarElement() != keyword) {
				return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
			}
			return List.of(result -> result.remove(first.getPreviousHiddenRegion(), value.getNextHiddenRegion()));
		}
		if (owner.eIsSet(feature) && value == null && isTrailing(assignment.eContainer())) {
			String text = serializeValue(owner, feature, assignment);
			ISemanticRegion last = lastSemanticRegion(ownerRegion);
			if (text == null || last == null) {
				return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
			}
			return List.of(new ReplaceRegionStrategy(last, last.getText() + " " + keyword.getValue() + " " + text));
		}
		return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
	}

	/** The keyword of an optional group {@code ('kw' feature=Value)?}, else null. */
	private static Keyword leadingKeyword(Assignment assignment) {
		if (assignment != null && assignment.eContainer() instanceof Group group && group.getElements().size() == 2
				&& group.getElements().get(0) instanceof Keyword keyword && group.getElements().get(1) == assignment
				&& ("?".equals(group.getCardinality()) || group.eContainer() instanceof UnorderedGroup)) {
			return keyword;
		}
		return null;
	}

	/** Whether nothing but optional elements may follow the element up to the end of its rule. */
	private static boolean isTrailing(EObject element) {
		while (element instanceof AbstractElement current && !(current.eContainer() instanceof ParserRule)) {
			EObject container = current.eContainer();
			if (container instanceof Group group) {
				List<AbstractElement> elements = group.getElements();
				for (AbstractElement after : elements.subList(elements.indexOf(current) + 1, elements.size())) {
					if (!GrammarUtil.isOptionalCardinality(after)) {
						return false;
					}
				}
			} else if (!(container instanceof UnorderedGroup)) {
				return false; // inside alternatives: cannot tell where the statement ends
			}
			element = container;
		}
		return true;
	}

	private String serializeValue(EObject owner, EStructuralFeature feature, Assignment assignment) {
		Object value = owner.eGet(feature);
		if (assignment.getTerminal() instanceof RuleCall call) {
			return valueSerializer.serializeAssignedValue(owner, call, value, null, errors);
		}
		if (assignment.getTerminal() instanceof CrossReference reference) {
			return crossReferenceSerializer.serializeCrossRef(owner, reference, (EObject) value, null, errors);
		}
		return null;
	}

	private static ISemanticRegion lastSemanticRegion(IEObjectRegion region) {
		ISemanticRegion last = null;
		for (ISemanticRegion semantic : region.getAllSemanticRegions()) {
			last = semantic;
		}
		return last;
	}
}
