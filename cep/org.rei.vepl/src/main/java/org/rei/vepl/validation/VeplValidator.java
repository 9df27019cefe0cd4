/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.validation;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsProvider;
import org.eclipse.xtext.validation.Check;
import org.rei.vepl.compiler.Alternatives;
import org.rei.vepl.runtime.MissionEvent;
import org.rei.vepl.vepl.AtomicEvent;
import org.rei.vepl.vepl.Bounded;
import org.rei.vepl.vepl.ComplexEvent;
import org.rei.vepl.vepl.Element;
import org.rei.vepl.vepl.Event;
import org.rei.vepl.vepl.EventRef;
import org.rei.vepl.vepl.Expression;
import org.rei.vepl.vepl.FollowedBy;
import org.rei.vepl.vepl.Multiplicity;
import org.rei.vepl.vepl.Not;
import org.rei.vepl.vepl.PatternFile;
import org.rei.vepl.vepl.QueryEvent;
import org.rei.vepl.vepl.Rule;
import org.rei.vepl.vepl.Signal;
import org.rei.vepl.vepl.VeplPackage.Literals;
import org.rei.vepl.vepl.Window;

import com.google.inject.Inject;

/** The rules a pattern file must follow before it is compiled; one check per rule, codes in {@link VeplIssueCodes}. */
public class VeplValidator extends AbstractVeplValidator {

	@Inject
	private ResourceDescriptionsProvider descriptions;

	@Inject
	private IQualifiedNameProvider names;

	/** The events of the mission topic (docs/protocol.md): the mission's, then the fault window edges. */
	public static final List<String> MISSION_EVENTS = MissionEvent.ALL;

	@Check
	public void checkUniqueNames(PatternFile file) {
		Map<String, EObject> events = new HashMap<>();
		Map<String, EObject> signals = new HashMap<>();
		Map<String, EObject> rules = new HashMap<>();
		for (Element e : file.getElements()) {
			Map<String, EObject> seen = e instanceof Event ? events : e instanceof Signal ? signals : rules;
			String name = e.getName();
			EObject first = name == null ? null : seen.putIfAbsent(name, e);
			if (first != null) {
				error("Duplicate name '" + name + "': it is already used on line " + line(first), e, Literals.ELEMENT__NAME,
						VeplIssueCodes.DUPLICATE_NAME);
			}
		}
	}

	/**
	 * Names are global over the files loaded together: every file the loader loads (the defaults and a
	 * {@code --patterns} folder), in an editor the .vepl files of the same folder (what {@code --patterns DIR}
	 * loads). The other files are those the scope sees: the loader's resource set, the language server's index.
	 */
	@Check
	public void checkUniqueNamesAcrossFiles(PatternFile file) {
		Resource own = file.eResource();
		IResourceDescriptions index = descriptions.getResourceDescriptions(own);
		for (Element e : file.getElements()) {
			QualifiedName name = e.getName() == null ? null : names.getFullyQualifiedName(e);
			if (name == null) {
				continue;
			}
			EClass kind = e instanceof Event ? Literals.EVENT : e instanceof Signal ? Literals.SIGNAL : Literals.RULE;
			for (IEObjectDescription other : index.getExportedObjects(kind, name, false)) {
				URI where = other.getEObjectURI().trimFragment();
				if (!where.equals(own.getURI()) && loadedTogether(own.getURI(), where)) {
					error("Duplicate name '" + e.getName() + "': " + kind.getName().toLowerCase() + " " + e.getName()
							+ " is also declared in " + declaredAt(own, other)
							+ " (names are global over the files loaded together)", e, Literals.ELEMENT__NAME,
							VeplIssueCodes.DUPLICATE_NAME);
					break;
				}
			}
		}
	}

	/** Files on disk when they share a folder; the loader's sources (not files) always. */
	private static boolean loadedTogether(URI one, URI other) {
		return !(one.isFile() && other.isFile()) || one.trimSegments(1).equals(other.trimSegments(1));
	}

	/** "NAME.vepl on line N", the line when the other file can be read. */
	private static String declaredAt(Resource own, IEObjectDescription other) {
		String file = other.getEObjectURI().trimFragment().lastSegment();
		try {
			EObject o = own.getResourceSet() == null ? null : own.getResourceSet().getEObject(other.getEObjectURI(), true);
			return o == null ? file : file + " on line " + line(o);
		} catch (RuntimeException e) { // the other file went away: its name is what the index knows
			return file;
		}
	}

	@Check
	public void checkHeader(PatternFile file) {
		if (file.getPackage() != null) {
			warning("REI ignores VIATRA-CEP's package: events, signals and rules are global across the loaded files",
					file, Literals.PATTERN_FILE__PACKAGE, VeplIssueCodes.IGNORED_HEADER);
		}
		for (var i : file.getImports()) {
			warning("REI ignores imports: queries are found by name among the loaded DRL queries (queries/)", i,
					null, VeplIssueCodes.IGNORED_HEADER);
		}
	}

	@Check
	public void checkNoActionBlock(Rule rule) {
		if (rule.getAction() != null) {
			error("A rule in REI publishes signals instead of running an action block: write 'rule \"" + rule.getName()
					+ "\" on " + (rule.getEvent() != null && !rule.getEvent().eIsProxy() ? rule.getEvent().getName()
							: "EVENT") + " emits SIG_NAME' with a 'signal SIG_NAME' declaration (docs/vepl.md)",
					rule, Literals.RULE__ACTION, VeplIssueCodes.ACTION_BLOCK);
		}
	}

	@Check
	public void checkTransitionIsOneStep(Signal s) {
		if (s.isTransition() && Math.abs(s.getFrom().getValue() - s.getTo().getValue()) != 1) {
			error("A transition is one step between neighbouring zones (FAR <-> CLOSE <-> COLLISION), got "
					+ s.getFrom().getName() + " -> " + s.getTo().getName()
					+ ": a jump over CLOSE is two signals at the same time", s, Literals.SIGNAL__TO,
					VeplIssueCodes.TRANSITION_STEP);
		}
	}

	@Check
	public void checkQueryIsKnown(QueryEvent e) {
		Set<String> known = KnownQueries.of(e.eResource());
		if (e.getQuery() != null && !known.contains(KnownQueries.resolve(e.getQuery()))) {
			error("Unknown query '" + e.getQuery() + "': the loaded queries are " + String.join(", ", known), e,
					Literals.QUERY_EVENT__QUERY, VeplIssueCodes.UNKNOWN_QUERY);
		}
	}

	@Check
	public void checkMissionEventIsKnown(AtomicEvent e) {
		if (e.getMission() != null && !MISSION_EVENTS.contains(e.getMission())) {
			error("Unknown mission event '" + e.getMission() + "': one of " + String.join(", ", MISSION_EVENTS), e,
					Literals.ATOMIC_EVENT__MISSION, VeplIssueCodes.UNKNOWN_MISSION_EVENT);
		}
	}

	@Check
	public void checkWindowFitsEnclosingWindow(Window w) {
		Window outer = enclosingWindow(w.eContainer().eContainer());
		if (outer != null && outer.getMillis() < w.getMillis()) {
			error("Contradictory windows: [" + w.getMillis() + "] lies inside [" + outer.getMillis()
					+ "], so its events can never be further apart than " + outer.getMillis() + " ms", w,
					Literals.WINDOW__MILLIS, VeplIssueCodes.CONTRADICTORY_WINDOW);
		}
	}

	@Check
	public void checkNegationOperandIsOneEvent(Not n) {
		if (!(n.getOperand() instanceof EventRef r) || r.getEvent() instanceof ComplexEvent) {
			error("NOT applies to one query or atomic event", n, Literals.NOT__OPERAND, VeplIssueCodes.NEGATION_OPERAND);
		}
	}

	@Check
	public void checkNegationIsInSequence(Not n) {
		if (!(n.eContainer() instanceof FollowedBy)
				|| Alternatives.items(chain(n)).stream().allMatch(i -> i instanceof Not)) {
			error("NOT needs a positive event before or after it in a followed-by (->) sequence", n, null,
					VeplIssueCodes.NEGATION_PLACE);
		}
	}

	@Check
	public void checkOpenNegationHasWindow(Not n) {
		if (!(n.eContainer() instanceof FollowedBy)) {
			return;
		}
		List<Expression> items = Alternatives.items(chain(n));
		boolean open = items.get(0) == n || items.get(items.size() - 1) == n;
		if (open && enclosingWindow(n) == null) {
			error("NOT at the start or end of a sequence needs a window, e.g. (a -> NOT b)[1000]: without one it "
					+ "could never be decided", n, null, VeplIssueCodes.UNBOUNDED_NEGATION);
		}
	}

	@Check
	public void checkMultiplicityCanMatch(Multiplicity m) {
		Bounded b = (Bounded) m.eContainer();
		if (!m.isAtLeastOnce() && !m.isAnyNumber() && m.getCount() == 0) {
			error("{0} matches nothing", m, Literals.MULTIPLICITY__COUNT, VeplIssueCodes.EMPTY_MATCH);
		} else if (m.isAnyNumber() && (!(b.eContainer() instanceof FollowedBy) || Alternatives.items(chain(b)).stream()
				.allMatch(i -> i instanceof Not || i instanceof Bounded x && x.getMultiplicity() != null
						&& x.getMultiplicity().isAnyNumber()))) {
			error("{*} also matches no event at all: use it beside other events in a followed-by (->) sequence", m,
					Literals.MULTIPLICITY__ANY_NUMBER, VeplIssueCodes.EMPTY_MATCH);
		}
	}

	@Check
	public void checkNotCyclic(ComplexEvent c) {
		Deque<ComplexEvent> todo = new ArrayDeque<>();
		Set<ComplexEvent> seen = new HashSet<>();
		todo.add(c);
		while (!todo.isEmpty()) {
			for (var it = EcoreUtil.<EObject>getAllContents(todo.pop(), true); it.hasNext();) {
				if (it.next() instanceof EventRef r && r.getEvent() instanceof ComplexEvent d && !d.eIsProxy()) {
					if (d == c) {
						error("Complex event '" + c.getName() + "' refers to itself", c, Literals.ELEMENT__NAME,
								VeplIssueCodes.CYCLIC_EVENT);
						return;
					}
					if (seen.add(d)) {
						todo.add(d);
					}
				}
			}
		}
	}

	@Check
	public void checkOneRulePerEvent(Rule r) {
		PatternFile file = (PatternFile) r.eContainer();
		for (Element e : file.getElements()) {
			if (e == r) {
				return;
			}
			if (e instanceof Rule other && other.getEvent() == r.getEvent() && !r.getEvent().eIsProxy()) {
				error("Event '" + r.getEvent().getName() + "' already has the rule on line " + line(other)
						+ ": list every signal there (one match, one rule)", r, Literals.RULE__EVENT,
						VeplIssueCodes.SECOND_RULE);
			}
		}
	}

	/** The top of the followed-by chain that {@code e} is an operand of. */
	private static Expression chain(EObject e) {
		EObject top = e;
		while (top.eContainer() instanceof FollowedBy f) {
			top = f;
		}
		return (Expression) top;
	}

	private static Window enclosingWindow(EObject from) {
		for (EObject o = from; o != null && !(o instanceof ComplexEvent); o = o.eContainer()) {
			if (o instanceof Bounded b && b.getWindow() != null) {
				return b.getWindow();
			}
		}
		return null;
	}

	private static int line(EObject o) {
		return NodeModelUtils.getNode(o).getStartLine();
	}
}
