/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.compiler;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.rei.vepl.validation.KnownQueries;
import org.rei.vepl.vepl.And;
import org.rei.vepl.vepl.AtomicEvent;
import org.rei.vepl.vepl.Bounded;
import org.rei.vepl.vepl.ComplexEvent;
import org.rei.vepl.vepl.Event;
import org.rei.vepl.vepl.EventRef;
import org.rei.vepl.vepl.Expression;
import org.rei.vepl.vepl.FollowedBy;
import org.rei.vepl.vepl.Not;
import org.rei.vepl.vepl.Or;
import org.rei.vepl.vepl.QueryEvent;

/**
 * Expands a VEPL expression into alternatives without OR, repetition or nested complex events: each is a set of
 * event occurrences ({@link Atom}) with bounds on their time differences ({@link Bound}) and events that must not
 * occur in an interval ({@link Absence}). Each alternative becomes one DRL rule.
 */
public final class Alternatives {

	/** What an occurrence matches: a query's FOUND/LOST, or a mission event kind. */
	record Type(String query, String kind, String mission) {
		boolean isMission() {
			return mission != null;
		}
	}

	/** One event occurrence of a match; {@code index} is its position in the rule. */
	static final class Atom {
		final Type type;
		int index;

		Atom(Type type) {
			this.type = type;
		}

		String var() {
			return "$e" + index;
		}
	}

	/** {@code lo <= later.timestamp - earlier.timestamp <= hi}; null means unbounded. */
	static final class Bound {
		final Atom from;
		final Atom to;
		Long lo;
		Long hi;

		Bound(Atom from, Atom to) {
			this.from = from;
			this.to = to;
		}
	}

	/**
	 * No event of {@code type} at or after every atom of {@code after} and at or before every atom of
	 * {@code before}; an open side is closed by {@code window} (the innermost enclosing window).
	 */
	static final class Absence {
		final Type type;
		final List<Atom> after = new ArrayList<>();
		final List<Atom> before = new ArrayList<>();
		Long window;

		Absence(Type type) {
			this.type = type;
		}
	}

	/** One alternative: atoms in rule order, bounds, absences, and types that may repeat inside a match. */
	static final class Alt {
		final List<Atom> atoms = new ArrayList<>();
		final Map<List<Atom>, Bound> bounds = new LinkedHashMap<>();
		final List<Absence> absences = new ArrayList<>();
		final Set<Type> tolerated = new LinkedHashSet<>();

		Alt copy() {
			Alt a = new Alt();
			a.atoms.addAll(atoms);
			for (Bound b : bounds.values()) {
				Bound c = a.bound(b.from, b.to);
				c.lo = b.lo;
				c.hi = b.hi;
			}
			for (Absence x : absences) {
				Absence y = new Absence(x.type);
				y.after.addAll(x.after);
				y.before.addAll(x.before);
				y.window = x.window;
				a.absences.add(y);
			}
			a.tolerated.addAll(tolerated);
			return a;
		}

		/** A copy with atoms of its own. */
		Alt fresh() {
			Map<Atom, Atom> m = new java.util.IdentityHashMap<>();
			Alt a = new Alt();
			for (Atom x : atoms) {
				Atom y = new Atom(x.type);
				m.put(x, y);
				a.atoms.add(y);
			}
			for (Bound b : bounds.values()) {
				Bound c = a.bound(m.get(b.from), m.get(b.to));
				c.lo = b.lo;
				c.hi = b.hi;
			}
			for (Absence x : absences) {
				Absence y = new Absence(x.type);
				x.after.forEach(t -> y.after.add(m.get(t)));
				x.before.forEach(t -> y.before.add(m.get(t)));
				y.window = x.window;
				a.absences.add(y);
			}
			a.tolerated.addAll(tolerated);
			return a;
		}

		Bound bound(Atom from, Atom to) {
			return bounds.computeIfAbsent(List.of(from, to), k -> new Bound(from, to));
		}

		void atLeast(Atom from, Atom to, long lo) {
			Bound b = bound(from, to);
			b.lo = b.lo == null ? lo : Math.max(b.lo, lo);
		}

		void atMost(Atom from, Atom to, long hi) {
			Bound b = bound(from, to);
			b.hi = b.hi == null ? hi : Math.min(b.hi, hi);
		}

		Alt merge(Alt other) {
			Alt a = copy();
			Alt o = other.copy();
			a.atoms.addAll(o.atoms);
			a.bounds.putAll(o.bounds);
			a.absences.addAll(o.absences);
			a.tolerated.addAll(o.tolerated);
			return a;
		}

		/** The set of atom types of this alternative, in rule order. */
		Set<Type> types() {
			Set<Type> t = new LinkedHashSet<>();
			atoms.forEach(x -> t.add(x.type));
			return t;
		}
	}

	private Alternatives() {
	}

	/** The alternatives of a complex event's expression (or of a single event), atoms numbered in rule order. */
	static List<Alt> of(Event event) {
		List<Alt> alts = event instanceof ComplexEvent c ? expand(c.getExpression(), true, new ArrayList<>())
				: List.of(single(event));
		List<Alt> out = new ArrayList<>();
		for (Alt shared : alts) {
			if (shared.atoms.isEmpty()) {
				continue; // matches the empty trace: rejected by validation, never a rule
			}
			Alt a = shared.fresh(); // alternatives share atoms of common operands; a rule numbers its own
			for (int i = 0; i < a.atoms.size(); i++) {
				a.atoms.get(i).index = i;
			}
			out.add(a);
		}
		return out;
	}

	static Type type(Event e) {
		if (e instanceof QueryEvent q) {
			return new Type(KnownQueries.resolve(q.getQuery()), q.getKind().getName().toUpperCase(), null);
		}
		if (e instanceof AtomicEvent a) {
			return new Type(null, null, a.getMission());
		}
		throw new IllegalArgumentException("not a simple event: " + e.getName());
	}

	private static Alt single(Event e) {
		Alt a = new Alt();
		a.atoms.add(new Atom(type(e)));
		return a;
	}

	private static List<Alt> expand(Expression e, boolean root, List<ComplexEvent> inlining) {
		if (e instanceof EventRef r) {
			Event ev = r.getEvent();
			if (ev instanceof ComplexEvent c) {
				if (inlining.contains(c)) {
					throw new IllegalArgumentException("complex event " + c.getName() + " refers to itself");
				}
				inlining.add(c);
				List<Alt> inner = expand(c.getExpression(), false, inlining);
				inlining.remove(inlining.size() - 1);
				return inner;
			}
			return List.of(single(ev));
		}
		if (e instanceof Or o) {
			List<Alt> out = new ArrayList<>(expand(o.getLeft(), false, inlining));
			out.addAll(expand(o.getRight(), false, inlining));
			return out;
		}
		if (e instanceof And a) {
			List<Alt> out = new ArrayList<>();
			List<Alt> right = expand(a.getRight(), false, inlining);
			for (Alt l : expand(a.getLeft(), false, inlining)) {
				for (Alt r : right) {
					out.add(l.merge(r));
				}
			}
			return out;
		}
		if (e instanceof FollowedBy f) {
			return sequence(items(f), inlining);
		}
		if (e instanceof Bounded b) {
			List<Alt> out;
			if (b.getMultiplicity() == null) {
				out = expand(b.getOperand(), false, inlining);
			} else if (b.getMultiplicity().isAnyNumber()) {
				// zero occurrences; inside an immediate sequence its events may still come in between
				Alt none = new Alt();
				for (Alt x : expand(b.getOperand(), false, inlining)) {
					none.tolerated.addAll(x.types());
				}
				out = List.of(none);
			} else if (b.getMultiplicity().isAtLeastOnce()) {
				// one occurrence is a match; further ones inside a sequence do not break an immediate match
				out = expand(b.getOperand(), false, inlining);
				if (!root) {
					for (Alt x : out) {
						x.tolerated.addAll(x.types());
					}
				}
			} else {
				List<Expression> copies = new ArrayList<>();
				for (int i = 0; i < b.getMultiplicity().getCount(); i++) {
					copies.add(b.getOperand());
				}
				out = sequence(copies, inlining);
			}
			if (b.getWindow() != null) {
				long w = b.getWindow().getMillis();
				for (Alt x : out) {
					window(x, w);
				}
			}
			return out;
		}
		if (e instanceof Not) {
			throw new IllegalArgumentException("NOT is only allowed as an operand of ->");
		}
		throw new IllegalArgumentException("unknown expression " + e.eClass().getName());
	}

	/** The operands of a chain of followed-by, left to right (the operator is associative). */
	public static List<Expression> items(Expression e) {
		List<Expression> out = new ArrayList<>();
		if (e instanceof FollowedBy f) {
			out.addAll(items(f.getLeft()));
			out.addAll(items(f.getRight()));
		} else {
			out.add(e);
		}
		return out;
	}

	private static List<Alt> sequence(List<Expression> items, List<ComplexEvent> inlining) {
		// each partial alternative remembers the atoms of the last positive operand and the absences still open
		record Partial(Alt alt, List<Atom> last, List<Absence> open) {
		}
		List<Partial> partials = List.of(new Partial(new Alt(), List.of(), List.of()));
		for (Expression item : items) {
			List<Partial> next = new ArrayList<>();
			if (item instanceof Not n) {
				Type t = type(((EventRef) n.getOperand()).getEvent());
				for (Partial p : partials) {
					Alt a = p.alt.copy();
					Absence x = new Absence(t);
					x.after.addAll(map(p.last, p.alt, a));
					a.absences.add(x);
					List<Absence> open = new ArrayList<>(remap(p.open, p.alt, a));
					open.add(x);
					next.add(new Partial(a, map(p.last, p.alt, a), open));
				}
			} else {
				List<Alt> options = expand(item, false, inlining);
				for (Partial p : partials) {
					for (Alt o : options) {
						Alt a = p.alt.merge(o);
						List<Atom> added = a.atoms.subList(p.alt.atoms.size(), a.atoms.size());
						List<Atom> last = map(p.last, p.alt, a);
						for (Atom from : last) {
							for (Atom to : added) {
								a.atLeast(from, to, 0);
							}
						}
						for (Absence x : remap(p.open, p.alt, a)) {
							x.before.addAll(added);
						}
						next.add(new Partial(a, added.isEmpty() ? last : List.copyOf(added), List.of()));
					}
				}
			}
			partials = next;
		}
		return partials.stream().map(Partial::alt).toList();
	}

	// Alt.copy/merge keep the same Atom objects and copy absences in order: positions map old to new
	private static List<Atom> map(List<Atom> atoms, Alt from, Alt to) {
		return atoms;
	}

	private static List<Absence> remap(List<Absence> open, Alt from, Alt to) {
		List<Absence> out = new ArrayList<>();
		for (Absence x : open) {
			out.add(to.absences.get(from.absences.indexOf(x)));
		}
		return out;
	}

	/** Every pair of atoms at most {@code w} ms apart; absences with an open side get the window. */
	private static void window(Alt a, long w) {
		for (int i = 0; i < a.atoms.size(); i++) {
			for (int j = i + 1; j < a.atoms.size(); j++) {
				Atom x = a.atoms.get(i);
				Atom y = a.atoms.get(j);
				a.atMost(x, y, w);
				a.atLeast(x, y, -w);
			}
		}
		for (Absence x : a.absences) {
			if (x.window == null && (x.after.isEmpty() || x.before.isEmpty())) {
				x.window = w;
			}
		}
	}
}
