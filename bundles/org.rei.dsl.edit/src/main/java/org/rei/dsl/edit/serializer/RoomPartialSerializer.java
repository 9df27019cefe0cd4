/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.serializer;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.change.FeatureChange;
import org.eclipse.emf.ecore.change.ListChange;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.AbstractElement;
import org.eclipse.xtext.Alternatives;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.EnumLiteralDeclaration;
import org.eclipse.xtext.EnumRule;
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
import org.eclipse.xtext.formatting2.regionaccess.ITextRegionDiffBuilder;
import org.eclipse.xtext.ide.serializer.impl.ChangeTreeProvider.EObjectChange;
import org.eclipse.xtext.ide.serializer.impl.PartialSerializer;
import org.eclipse.xtext.serializer.ISerializationContext;
import org.eclipse.xtext.serializer.acceptor.ISemanticSequenceAcceptor;
import org.eclipse.xtext.serializer.acceptor.ISequenceAcceptor;
import org.eclipse.xtext.serializer.acceptor.ISyntacticSequenceAcceptor;
import org.eclipse.xtext.serializer.acceptor.TokenStreamSequenceAdapter;
import org.eclipse.xtext.serializer.analysis.IGrammarConstraintProvider.IConstraint;
import org.eclipse.xtext.serializer.analysis.IGrammarConstraintProvider.IConstraintElement;
import org.eclipse.xtext.serializer.diagnostic.ISerializationDiagnostic;
import org.eclipse.xtext.serializer.sequencer.IHiddenTokenSequencer;
import org.eclipse.xtext.serializer.sequencer.ISemanticSequencer;
import org.eclipse.xtext.serializer.sequencer.ISyntacticSequencer;
import org.eclipse.xtext.serializer.tokens.ICrossReferenceSerializer;
import org.eclipse.xtext.serializer.tokens.IValueSerializer;
import org.rei.dsl.derived.DerivedMarker;

import com.google.inject.Inject;
import com.google.inject.Provider;

/**
 * Xtext's partial serializer with five gaps closed that the REI grammar runs into; without them a small edit
 * re-serializes a whole room (derived floors included) or leaves a keyword without its value.
 * <ul>
 * <li>A list inside a repeated group of alternatives ({@code (ownedBlocks+=.. | ownedObjects+=.. | ..)*}) is not
 * "many" to the constraint analysis (each assignment is optional, the group repeats), so adding or deleting one
 * object fell back to the enclosing room: here such list changes become region deletions and insertions, in a way
 * that suits the diff builder (see {@link #serializeContainmentList}).</li>
 * <li>Unsetting an optional {@code 'yaw' yaw=Number} deleted "90" and kept "yaw": the keyword goes with it.</li>
 * <li>Setting such a value where the text has none re-serialized the whole statement: a trailing optional group
 * is appended after the statement's last token instead, so the rest of the line keeps its text.</li>
 * <li>A changed enum value (a route's behaviour) went to the value converters, which cannot write one: its
 * keyword replaces the written one, or follows the statement's last token.</li>
 * <li>A flag turned off inside a group of options in any order ({@code loop?='loop'}) took the options written after
 * it along: only its keyword is deleted; neighbouring options deleted together leave one space.</li>
 * </ul>
 */
public class RoomPartialSerializer extends PartialSerializer {

	@Inject
	private IValueSerializer valueSerializer;

	@Inject
	private ICrossReferenceSerializer crossReferenceSerializer;

	@Inject
	private Provider<ISemanticSequencer> semanticSequencers;

	@Inject
	private Provider<ISyntacticSequencer> syntacticSequencers;

	@Inject
	private Provider<IHiddenTokenSequencer> hiddenTokenSequencers;

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
		if (feature instanceof EReference reference && !reference.isContainment()) {
			List<SerializationStrategy> list = serializeReferenceList(owner, reference, ownerRegion);
			if (list != null) {
				return list;
			}
		}
		return super.trySerializeMultiValue(owner, change, ownerRegion, constraint);
	}

	/**
	 * A list of cross-references written {@code '[' x+=[T] (',' x+=[T])* ']'} (a crowd's areas): Xtext re-writes
	 * the whole statement for any change of one, losing its layout. Here the names between the brackets are
	 * re-written and nothing else: the first written name's place takes the whole new list, the others go with
	 * their commas (the removal starts where that replacement ends, which the diff builder writes right here).
	 * Null (Xtext's way) for a list written otherwise or that would be empty.
	 */
	private List<SerializationStrategy> serializeReferenceList(EObject owner, EReference feature,
			IEObjectRegion ownerRegion) {
		List<ISemanticRegion> written = ownerRegion.getRegionFor().features(feature);
		List<?> now = (List<?>) owner.eGet(feature);
		CrossReference reference = written.isEmpty() ? null
				: GrammarUtil.containingCrossReference(written.get(0).getGrammarElement());
		if (reference == null || now.isEmpty()) {
			return null;
		}
		ISemanticRegion first = written.get(0);
		ISemanticRegion last = written.get(written.size() - 1);
		List<String> names = new ArrayList<>();
		for (Object target : now) {
			names.add(crossReferenceSerializer.serializeCrossRef(owner, reference, (EObject) target, null, errors));
		}
		if (written.size() == 1) {
			return List.of(new ReplaceWords(first, String.join(", ", names)));
		}
		IHiddenRegion afterFirst = first.getNextHiddenRegion();
		IHiddenRegion afterLast = last.getNextHiddenRegion();
		return List.of(new ReplaceWords(first, String.join(", ", names)), edits -> edits.remove(afterFirst, afterLast));
	}

	/**
	 * Old list = the elements with a region in the original text (in text order), new list = the feature's value.
	 * The longest run of elements that kept their order stays as it is; between two of them (a gap) the others are
	 * deleted and the new or moved ones written. Rewrites of Xtext's diff builder must not share a boundary, so a
	 * gap's insertion replaces its first deleted run when it has one, and a gap takes one insertion at most (a batch
	 * that needs more is split by the document).
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
		List<EObject> anchors = now.stream().filter(stable::contains).toList();
		List<SerializationStrategy> result = new ArrayList<>();
		int position = 0; // in now
		for (int gap = 0; gap <= anchors.size(); gap++) {
			int from = gap == 0 ? -1 : oldIndex.get(anchors.get(gap - 1));
			int to = gap == anchors.size() ? old.size() : oldIndex.get(anchors.get(gap));
			List<EObject> inserted = new ArrayList<>();
			while (position < now.size() && !stable.contains(now.get(position))) {
				inserted.add(now.get(position++));
			}
			position++; // the anchor
			if (inserted.size() > 1) {
				throw new TangledListException(feature);
			}
			List<List<IEObjectRegion>> runs = contiguousRuns(old.subList(from + 1, to));
			for (int r = 0; r < runs.size(); r++) {
				List<IEObjectRegion> run = runs.get(r);
				IHiddenRegion first = run.get(0).getPreviousHiddenRegion();
				IHiddenRegion last = run.get(run.size() - 1).getNextHiddenRegion();
				if (r == 0 && !inserted.isEmpty()) {
					result.add(write(first, last, inserted.get(0)));
				} else {
					result.add(edits -> edits.remove(first, last));
				}
			}
			if (runs.isEmpty() && !inserted.isEmpty()) {
				IHiddenRegion at = gap > 0 ? access.regionForEObject(anchors.get(gap - 1)).getNextHiddenRegion()
						: !anchors.isEmpty() ? access.regionForEObject(anchors.get(0)).getPreviousHiddenRegion()
								: beforeClosingBrace(ownerRegion);
				if (at == null) {
					return null;
				}
				result.add(write(at, at, inserted.get(0)));
			}
		}
		return result;
	}

	/** Regions that follow one another in the text with nothing but hidden tokens between them. */
	private static List<List<IEObjectRegion>> contiguousRuns(List<IEObjectRegion> regions) {
		List<List<IEObjectRegion>> runs = new ArrayList<>();
		for (IEObjectRegion region : regions) {
			List<IEObjectRegion> run = runs.isEmpty() ? null : runs.get(runs.size() - 1);
			if (run != null && run.get(run.size() - 1).getNextHiddenRegion() == region.getPreviousHiddenRegion()) {
				run.add(region);
			} else {
				List<IEObjectRegion> next = new ArrayList<>();
				next.add(region);
				runs.add(next);
			}
		}
		return runs;
	}

	private static IHiddenRegion beforeClosingBrace(IEObjectRegion owner) {
		List<ISemanticRegion> closing = owner.getRegionFor().keywords("}");
		return closing.isEmpty() ? null : closing.get(closing.size() - 1).getPreviousHiddenRegion();
	}

	/** Serializes {@code element} in place of the text from {@code first} to {@code last} (equal: inserts). */
	private SerializationStrategy write(IHiddenRegion first, IHiddenRegion last, EObject element) {
		ISerializationContext context = getSerializationContext(element);
		return edits -> {
			ISemanticSequencer semantic = semanticSequencers.get();
			ISyntacticSequencer syntactic = syntacticSequencers.get();
			IHiddenTokenSequencer hidden = hiddenTokenSequencers.get();
			semantic.init((ISemanticSequenceAcceptor) syntactic, errors);
			syntactic.init(context, element, (ISyntacticSequenceAcceptor) hidden, errors);
			ISequenceAcceptor acceptor = edits.replaceSequence(first, last, context, element);
			hidden.init(context, element, acceptor, errors);
			if (acceptor instanceof TokenStreamSequenceAdapter adapter) {
				adapter.init(context);
			}
			semantic.createSequence(context, element);
		};
	}

	/**
	 * The longest subsequence of {@code now} whose old indices increase: those elements need no edit (patience
	 * sorting, n log n: an explicit room may list ten thousand floors).
	 */
	private static Set<EObject> longestOrderedRun(List<EObject> now, Map<EObject, Integer> oldIndex) {
		List<EObject> kept = now.stream().filter(oldIndex::containsKey).toList();
		int n = kept.size();
		int[] tails = new int[n]; // tails[k]: index into kept of the smallest end of a run of length k + 1
		int[] previous = new int[n];
		int length = 0;
		for (int i = 0; i < n; i++) {
			int value = oldIndex.get(kept.get(i));
			int low = 0;
			int high = length;
			while (low < high) {
				int middle = (low + high) >>> 1;
				if (oldIndex.get(kept.get(tails[middle])) < value) {
					low = middle + 1;
				} else {
					high = middle;
				}
			}
			previous[i] = low > 0 ? tails[low - 1] : -1;
			tails[low] = i;
			length = Math.max(length, low + 1);
		}
		Set<EObject> result = new HashSet<>();
		for (int i = length > 0 ? tails[length - 1] : -1; i >= 0; i = previous[i]) {
			result.add(kept.get(i));
		}
		return result;
	}

	/**
	 * The changes of one element's options, merged where they touch, since the diff builder writes rewrites that
	 * share a boundary wrongly: removals of neighbouring options ({@code speed 0.8 loop} both set back to their
	 * defaults) share the hidden region between them and become one removal; options appended after the same last
	 * word ({@code start 2s} and {@code curious}) become one replacement of that word, which also takes in a new value
	 * of that word or its removal.
	 */
	@Override
	protected List<SerializationStrategy> trySerializeIndividualFeatures(EObjectChange change, IEObjectRegion original,
			ISerializationContext context, IConstraint constraint) {
		List<SerializationStrategy> strategies = super.trySerializeIndividualFeatures(change, original, context,
				constraint);
		if (strategies == null) {
			return null;
		}
		List<SerializationStrategy> result = new ArrayList<>();
		List<RemoveWords> removals = new ArrayList<>();
		Map<ISemanticRegion, String> replaced = new LinkedHashMap<>();
		Map<ISemanticRegion, List<String>> appended = new LinkedHashMap<>();
		for (SerializationStrategy strategy : strategies) {
			if (strategy instanceof RemoveWords removal) {
				removals.add(removal);
			} else if (strategy instanceof ReplaceWords replace) {
				replaced.put(replace.region(), replace.text());
			} else if (strategy instanceof AppendWords append) {
				appended.computeIfAbsent(append.after(), region -> new ArrayList<>()).add(append.text());
			} else {
				result.add(strategy);
			}
		}
		removals = merged(removals);
		for (Map.Entry<ISemanticRegion, List<String>> append : appended.entrySet()) {
			ISemanticRegion last = append.getKey();
			String words = String.join(" ", append.getValue());
			RemoveWords ending = removals.stream().filter(r -> r.last() == last.getNextHiddenRegion()).findFirst()
					.orElse(null);
			if (replaced.containsKey(last)) {
				replaced.put(last, replaced.get(last) + " " + words);
			} else if (ending != null) {
				// the last word goes: the appended words take its place
				removals.remove(ending);
				if (ending.first() != last.getPreviousHiddenRegion()) {
					removals.add(new RemoveWords(ending.first(), last.getPreviousHiddenRegion()));
				}
				replaced.put(last, words);
			} else {
				replaced.put(last, last.getText() + " " + words);
			}
		}
		result.addAll(removals);
		replaced.forEach((region, text) -> result.add(new ReplaceRegionStrategy(region, text)));
		return result;
	}

	/** Removals that share a boundary, as one. */
	private static List<RemoveWords> merged(List<RemoveWords> removals) {
		List<RemoveWords> sorted = new ArrayList<>(removals);
		sorted.sort(Comparator.comparingInt(removal -> removal.first().getOffset()));
		List<RemoveWords> result = new ArrayList<>();
		for (RemoveWords removal : sorted) {
			RemoveWords previous = result.isEmpty() ? null : result.get(result.size() - 1);
			if (previous != null && previous.last() == removal.first()) {
				result.set(result.size() - 1, new RemoveWords(previous.first(), removal.last()));
			} else {
				result.add(removal);
			}
		}
		return result;
	}

	/** Deletes the words between two hidden regions, and one of them. */
	private record RemoveWords(IHiddenRegion first, IHiddenRegion last) implements SerializationStrategy {
		@Override
		public void serialize(ITextRegionDiffBuilder result) {
			result.remove(first, last);
		}
	}

	/** Writes {@code text} instead of a word. */
	private record ReplaceWords(ISemanticRegion region, String text) implements SerializationStrategy {
		@Override
		public void serialize(ITextRegionDiffBuilder result) {
			result.replace(region, text);
		}
	}

	/** Writes {@code text} after a statement's last word, a space between. */
	private record AppendWords(ISemanticRegion after, String text) implements SerializationStrategy {
		@Override
		public void serialize(ITextRegionDiffBuilder result) {
			result.replace(after, after.getText() + " " + text);
		}
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
		AbstractElement optionElement = optionOf(assignment);
		if (optionElement != null) {
			List<SerializationStrategy> option = option(owner, feature, assignment, keyword, value, ownerRegion,
					isTrailing(optionElement));
			if (option != null) {
				return option;
			}
		}
		if (keyword == null) {
			return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
		}
		if (!owner.eIsSet(feature) && value != null) {
			ISemanticRegion first = value.getPreviousSemanticRegion();
			if (first == null || first.getGrammarElement() != keyword) {
				return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
			}
			return List.of(new RemoveWords(first.getPreviousHiddenRegion(), value.getNextHiddenRegion()));
		}
		if (owner.eIsSet(feature) && value == null && isTrailing(assignment.eContainer())) {
			String text = serializeValue(owner, feature, assignment);
			ISemanticRegion last = lastSemanticRegion(ownerRegion);
			if (text == null || last == null) {
				return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
			}
			return List.of(new AppendWords(last, keyword.getValue() + " " + text));
		}
		return super.trySerializeSingleValue(owner, change, ownerRegion, constraint);
	}

	/**
	 * A changed option of a group in any order (a route's {@code speed 1.1}, {@code start 3s}, {@code loop},
	 * {@code curious}), written word by word so that several changes of one element can be merged: a new value
	 * replaces the written one, an option the text left out is appended after the element's last word (the group
	 * ends its rule), one set back to its default is deleted with its keyword, a flag turned on replaces its
	 * alternative ({@code once}) where the text has it. An enum value is written as its keyword, also where it is
	 * the default (Xtext's own path hands it to the value converters, which cannot write one). Null: not such an
	 * option, Xtext's own path.
	 */
	private List<SerializationStrategy> option(EObject owner, EStructuralFeature feature, Assignment assignment,
			Keyword keyword, ISemanticRegion value, IEObjectRegion ownerRegion, boolean trailing) {
		ISemanticRegion last = lastSemanticRegion(ownerRegion);
		boolean set = owner.eIsSet(feature);
		String literal = enumKeyword(assignment, owner.eGet(feature));
		if (literal != null) {
			if (value != null) {
				return List.of(new ReplaceWords(value, literal));
			}
			return !set ? List.of() : last != null && trailing ? List.of(new AppendWords(last, literal)) : null;
		}
		if (isBooleanKeyword(assignment)) {
			Keyword flag = (Keyword) assignment.getTerminal();
			if (!set) {
				return value == null ? List.of()
						: List.of(new RemoveWords(value.getPreviousHiddenRegion(), value.getNextHiddenRegion()));
			}
			if (value != null) {
				return List.of();
			}
			ISemanticRegion other = alternativeKeyword(assignment, ownerRegion);
			if (other != null) {
				return List.of(new ReplaceWords(other, flag.getValue()));
			}
			return last != null && trailing ? List.of(new AppendWords(last, flag.getValue())) : null;
		}
		if (keyword == null) {
			return null;
		}
		if (set && value != null) {
			String text = serializeValue(owner, feature, assignment);
			return text == null ? null : List.of(new ReplaceWords(value, text));
		}
		if (set) {
			String text = serializeValue(owner, feature, assignment);
			return text == null || last == null || !trailing ? null
					: List.of(new AppendWords(last, keyword.getValue() + " " + text));
		}
		if (value == null) {
			return List.of();
		}
		ISemanticRegion next = value.getNextSemanticRegion();
		if (next != null && EcoreUtil.isAncestor(assignment.eContainer(), next.getGrammarElement())) {
			// the group goes on after the value ('speed 1.2 to 1.4'): the default is written, the rest stays
			String text = serializeValue(owner, feature, assignment);
			return text == null ? null : List.of(new ReplaceWords(value, text));
		}
		ISemanticRegion first = value.getPreviousSemanticRegion();
		return first == null || first.getGrammarElement() != keyword ? null
				: List.of(new RemoveWords(first.getPreviousHiddenRegion(), value.getNextHiddenRegion()));
	}

	/** The element of a group in any order ({@code &}) that holds the assignment, or null when none does. */
	private static AbstractElement optionOf(Assignment assignment) {
		EObject element = assignment;
		while (element instanceof AbstractElement current) {
			EObject container = current.eContainer();
			if (container instanceof UnorderedGroup) {
				return current;
			}
			if (!(container instanceof Group || container instanceof Alternatives)) {
				return null;
			}
			element = container;
		}
		return null;
	}

	/** The written keyword of the alternative to a flag ({@code once} of {@code (loop?='loop' | 'once')?}), or null. */
	private static ISemanticRegion alternativeKeyword(Assignment assignment, IEObjectRegion ownerRegion) {
		if (!(assignment.eContainer() instanceof Alternatives alternatives)) {
			return null;
		}
		for (ISemanticRegion region : ownerRegion.getSemanticRegions()) {
			EObject element = region.getGrammarElement();
			if (element instanceof Keyword && element != assignment.getTerminal()
					&& alternatives.getElements().contains(element)) {
				return region;
			}
		}
		return null;
	}

	/**
	 * The keyword of an optional group {@code ('kw' feature=Value)?}, or of one that goes on with optional parts
	 * ({@code ('speed' speed=Number ('to' speedTo=Number)?)?}); else null.
	 */
	private static Keyword leadingKeyword(Assignment assignment) {
		if (assignment != null && assignment.eContainer() instanceof Group group && group.getElements().size() >= 2
				&& group.getElements().get(0) instanceof Keyword keyword && group.getElements().get(1) == assignment
				&& group.getElements().subList(2, group.getElements().size()).stream()
						.allMatch(GrammarUtil::isOptionalCardinality)
				&& ("?".equals(group.getCardinality()) || group.eContainer() instanceof UnorderedGroup)) {
			return keyword;
		}
		return null;
	}

	/** {@code flag?='keyword'}. */
	private static boolean isBooleanKeyword(Assignment assignment) {
		return assignment != null && "?=".equals(assignment.getOperator()) && assignment.getTerminal() instanceof Keyword;
	}

	/** The keyword an enum rule writes {@code value} with, when the assignment calls an enum rule; else null. */
	private static String enumKeyword(Assignment assignment, Object value) {
		if (assignment == null || !(assignment.getTerminal() instanceof RuleCall call)
				|| !(call.getRule() instanceof EnumRule rule) || value == null) {
			return null;
		}
		for (EnumLiteralDeclaration declaration : EcoreUtil2.getAllContentsOfType(rule, EnumLiteralDeclaration.class)) {
			if (declaration.getEnumLiteral() != null && declaration.getEnumLiteral().getInstance() == value) {
				return declaration.getLiteral().getValue();
			}
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
