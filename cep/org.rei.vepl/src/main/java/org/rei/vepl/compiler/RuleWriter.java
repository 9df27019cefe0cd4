/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.compiler;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.rei.vepl.compiler.Alternatives.Absence;
import org.rei.vepl.compiler.Alternatives.Alt;
import org.rei.vepl.compiler.Alternatives.Atom;
import org.rei.vepl.compiler.Alternatives.Bound;
import org.rei.vepl.compiler.Alternatives.Type;

/**
 * Writes one alternative as a DRL rule. Semantics (docs/vepl.md):
 * <ul>
 * <li>All events of a match have the same subject; {@code ->} is "not earlier" on timestamps (events of one message
 * are simultaneous and match in either order); windows bound every pair of the operand's events.
 * <li>An event is used by at most one match per file (the consumption scope): a {@code VeplUsed} fact records it,
 * so patterns of other files never lose events to this one.
 * <li>chronicle: the oldest unused initiator (first event) that fits is taken; partial matches wait for the window.
 * <li>immediate: no event of the pattern's own types (except repetitions a {@code {+}}/{@code {*}} inside a sequence
 * allows) lies strictly between the match's first and last event; so the latest initiator is taken and older
 * partial matches are dead.
 * </ul>
 */
final class RuleWriter {

	private final DrlTarget target;
	private final String scope;
	private final StringBuilder out = new StringBuilder();

	RuleWriter(DrlTarget target, String scope) {
		this.target = target;
		this.scope = scope;
	}

	String text() {
		return out.toString();
	}

	void rule(String name, String origin, Alt alt, boolean immediate, List<String> signals) {
		out.append("rule \"").append(escape(name)).append("\"\n");
		out.append("    // ").append(origin).append('\n');
		out.append("when\n");
		Atom first = alt.atoms.get(0);
		String subject = first.var() + ".subject";
		for (Atom a : alt.atoms) {
			List<String> c = new ArrayList<>(typeConstraints(a.type));
			if (a.index > 0) {
				c.add("subject == " + subject);
				for (Atom b : alt.atoms.subList(0, a.index)) {
					if (b.type.equals(a.type)) { // events of other types differ already by their alpha constraints
						c.add("this != " + b.var());
					}
				}
				c.addAll(bounds(alt, a, "timestamp", a));
			}
			line(a.var() + " : " + cls(a.type) + "( " + String.join(", ", c) + " )");
			// one 'not' per event (Drools hash-indexes 'event == $x', not a disjunction), right after its event: used
			// events never reach the joins, and rules that start with the same event share the node
			line(notUsed(a.type, a.var()));
		}
		if (immediate) {
			contiguity(alt, subject);
		} else if (alt.atoms.size() > 1) {
			oldestInitiator(alt, first, subject);
		}
		for (Absence x : alt.absences) {
			absence(alt, x, subject);
		}
		out.append("then\n");
		for (Atom a : alt.atoms) {
			line("insert( new VeplUsed( \"" + scope + "\", \"" + usedType(a.type) + "\", " + a.var() + ", " + a.var()
					+ ".getTimestamp() ) );");
		}
		String observation = latest(alt);
		boolean delayed = alt.absences.stream().anyMatch(x -> x.before.isEmpty());
		for (String s : signals) {
			if (delayed) {
				// the match completes when the window closes: the time is the clock's, the message that moved it
				line("signals.emit( \"" + s + "\", kcontext.getKieRuntime().getSessionClock().getCurrentTime() / 1000.0, "
						+ observation + ".getSubject(), " + observation + ".getTarget(), " + observation
						+ ".getRange() );");
			} else {
				line("signals.emit( \"" + s + "\", " + observation + " );");
			}
		}
		out.append("end\n\n");
	}

	/**
	 * 'not used in this scope'. VeplUsed carries its event's type (a function of the event) besides the scope: both
	 * are hashed alpha constraints, so a VeplUsed reaches only the few 'not' nodes that check events of its type
	 * instead of every one of the file's, which made VeplUsed the costliest fact of the session.
	 */
	private String notUsed(Type t, String var) {
		return "not VeplUsed( scope == \"" + scope + "\", type == \"" + usedType(t) + "\", event == " + var + " )";
	}

	private static String usedType(Type t) {
		return t.isMission() ? "mission " + t.mission() : t.query() + " " + t.kind();
	}

	private void line(String s) {
		out.append("    ").append(s).append('\n');
	}

	private String cls(Type t) {
		return DrlTarget.simpleName(t.isMission() ? target.missionEvent() : target.queryEvent());
	}

	private List<String> typeConstraints(Type t) {
		if (t.isMission()) {
			return List.of("event == \"" + t.mission() + "\"");
		}
		return List.of("query == \"" + t.query() + "\"",
				"kind == " + DrlTarget.simpleName(target.queryEvent()) + ".Kind." + t.kind());
	}

	/**
	 * The bounds that constrain {@code of} against atoms bound before {@code placedAt} (all of them when
	 * {@code placedAt} is null), written for a pattern whose timestamp is {@code field}.
	 */
	private static List<String> bounds(Alt alt, Atom of, String field, Atom placedAt) {
		List<String> c = new ArrayList<>();
		for (Bound b : alt.bounds.values()) {
			Atom other;
			boolean ofIsLater;
			if (b.to == of) {
				other = b.from;
				ofIsLater = true;
			} else if (b.from == of) {
				other = b.to;
				ofIsLater = false;
			} else {
				continue;
			}
			if (placedAt != null && other.index >= placedAt.index) {
				continue; // written on the other atom's pattern
			}
			String ref = other.var() + ".timestamp";
			if (ofIsLater) { // lo <= of - other <= hi
				if (b.lo != null) {
					c.add(field + " >= " + plus(ref, b.lo));
				}
				if (b.hi != null) {
					c.add(field + " <= " + plus(ref, b.hi));
				}
			} else { // lo <= other - of <= hi
				if (b.lo != null) {
					c.add(field + " <= " + plus(ref, -b.lo));
				}
				if (b.hi != null) {
					c.add(field + " >= " + plus(ref, -b.hi));
				}
			}
		}
		return c;
	}

	private static String plus(String ref, long offset) {
		return offset == 0 ? ref : offset > 0 ? ref + " + " + offset : ref + " - " + (-offset);
	}

	/**
	 * immediate: nothing of the pattern's own (not tolerated) types strictly inside the match's span. One 'not' per
	 * type rather than one over a disjunction: the type constraints stay hashed, shared alpha nodes instead of an
	 * expression every inserted event is evaluated against.
	 */
	private void contiguity(Alt alt, String subject) {
		if (alt.atoms.size() < 2) {
			return;
		}
		Set<Type> named = new LinkedHashSet<>(alt.types());
		named.removeAll(alt.tolerated);
		String min = extreme(alt, true);
		String max = extreme(alt, false);
		for (Type t : named) {
			List<String> c = new ArrayList<>(typeConstraints(t));
			c.add("subject == " + subject);
			c.add("timestamp > " + min);
			c.add("timestamp < " + max);
			for (Atom a : alt.atoms) {
				// with two events each one is the span's min or max, which the strict bounds exclude
				if (a.type.equals(t) && alt.atoms.size() > 2) {
					c.add("this != " + a.var());
				}
			}
			line("not " + cls(t) + "( " + String.join(", ", c) + " )");
		}
	}

	/** chronicle: no older unused event of the initiator's type that fits the same bounds. */
	private void oldestInitiator(Alt alt, Atom first, String subject) {
		List<String> c = new ArrayList<>(typeConstraints(first.type));
		c.add("subject == " + subject);
		c.add("timestamp < " + first.var() + ".timestamp");
		for (Atom a : alt.atoms.subList(1, alt.atoms.size())) {
			if (a.type.equals(first.type)) {
				c.add("this != " + a.var());
			}
		}
		c.addAll(bounds(alt, first, "timestamp", null));
		line("not ( $older : " + cls(first.type) + "( " + String.join(", ", c) + " ) and " + notUsed(first.type, "$older")
				+ " )");
	}

	private void absence(Alt alt, Absence x, String subject) {
		List<String> c = new ArrayList<>(typeConstraints(x.type));
		c.add("subject == " + subject);
		for (Atom a : alt.atoms) {
			if (a.type.equals(x.type)) {
				c.add("this != " + a.var());
			}
		}
		if (x.before.isEmpty()) {
			// open end: Fusion decides the 'not' when the clock passes the operator's upper bound, before the events
			// of that instant are inserted: one ms more lets events of the window's last instant still cancel it
			Atom anchor = latestAtom(x.after);
			c.add("this after[ 0ms, " + (x.window + 1) + "ms ] " + anchor.var());
			c.add("timestamp <= " + plus(anchor.var() + ".timestamp", x.window));
			for (Atom a : x.after) {
				if (a != anchor) {
					c.add("timestamp >= " + a.var() + ".timestamp");
				}
			}
		} else {
			for (Atom a : x.after) {
				c.add("timestamp >= " + a.var() + ".timestamp");
			}
			for (Atom b : x.before) {
				c.add("timestamp <= " + b.var() + ".timestamp");
				if (x.after.isEmpty()) {
					c.add("timestamp >= " + plus(b.var() + ".timestamp", -x.window));
				}
			}
		}
		line("not " + cls(x.type) + "( " + String.join(", ", c) + " )");
	}

	/** The atom known to be no earlier than all others, else the last one in rule order. */
	private static Atom latestAtom(List<Atom> atoms) {
		for (Atom a : atoms) {
			if (atoms.stream().allMatch(b -> b == a || b.index < a.index)) {
				return a;
			}
		}
		return atoms.get(atoms.size() - 1);
	}

	/** An expression for the earliest (or latest) timestamp of the match. */
	private static String extreme(Alt alt, boolean earliest) {
		Atom known = ordered(alt, earliest);
		if (known != null) {
			return known.var() + ".timestamp";
		}
		String f = earliest ? "Math.min" : "Math.max";
		String e = alt.atoms.get(0).var() + ".timestamp";
		for (Atom a : alt.atoms.subList(1, alt.atoms.size())) {
			e = f + "( " + e + ", " + a.var() + ".timestamp )";
		}
		return e;
	}

	/** The atom that bounds say is not later (earliest) / not earlier than every other, or null. */
	private static Atom ordered(Alt alt, boolean earliest) {
		int n = alt.atoms.size();
		boolean[][] le = new boolean[n][n]; // le[i][j]: i.timestamp <= j.timestamp
		for (int i = 0; i < n; i++) {
			le[i][i] = true;
		}
		for (Bound b : alt.bounds.values()) {
			if (b.lo != null && b.lo >= 0) {
				le[b.from.index][b.to.index] = true;
			}
			if (b.hi != null && b.hi <= 0) {
				le[b.to.index][b.from.index] = true;
			}
		}
		for (int k = 0; k < n; k++) {
			for (int i = 0; i < n; i++) {
				for (int j = 0; j < n; j++) {
					le[i][j] |= le[i][k] && le[k][j];
				}
			}
		}
		for (int i = 0; i < n; i++) {
			boolean all = true;
			for (int j = 0; j < n && all; j++) {
				all = earliest ? le[i][j] : le[j][i];
			}
			if (all) {
				return alt.atoms.get(i);
			}
		}
		return null;
	}

	/** The observation a signal reports: the match's latest event (picked at run time when bounds do not say). */
	private String latest(Alt alt) {
		Atom known = ordered(alt, false);
		if (known != null) {
			return known.var();
		}
		String obs = DrlTarget.simpleName(target.observation());
		line(obs + " last = " + alt.atoms.get(0).var() + ";");
		for (Atom a : alt.atoms.subList(1, alt.atoms.size())) {
			line("if ( " + a.var() + ".getT() >= last.getT() ) { last = " + a.var() + "; }");
		}
		return "last";
	}

	static String escape(String s) {
		return s.replace("\\", "\\\\").replace("\"", "\\\"");
	}
}
