/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.documentation;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.rei.vepl.runtime.MissionEvent;
import org.rei.vepl.validation.KnownQueries;
import org.rei.vepl.vepl.AtomicEvent;
import org.rei.vepl.vepl.ComplexEvent;
import org.rei.vepl.vepl.QueryEvent;
import org.rei.vepl.vepl.QueryEventKind;
import org.rei.vepl.vepl.Signal;

/**
 * What an editor's hover shows on an event or a signal, wherever it is named (Markdown): what makes the event
 * happen, with its definition as written, and what a signal is worth and which zone change it declares.
 */
public class VeplDocumentationProvider implements IEObjectDocumentationProvider {

	@Override
	public String getDocumentation(EObject o) {
		if (o instanceof QueryEvent q) {
			String query = KnownQueries.resolve(q.getQuery());
			String alias = query.equals(q.getQuery()) ? "" : " (the thesis's name of REI's `" + query + "`)";
			return "**Query event " + q.getName() + "**: a match of the DRL query `" + q.getQuery() + "`" + alias
					+ (q.getKind() == QueryEventKind.FOUND ? " appears" : " disappears") + definition(o);
		}
		if (o instanceof AtomicEvent a) {
			boolean known = MissionEvent.ALL.contains(a.getMission());
			return "**Atomic event " + a.getName() + "**: the mission topic's `" + a.getMission() + "` event"
					+ (known ? "" : " (not one the mission topic carries: " + String.join(", ", MissionEvent.ALL) + ")")
					+ definition(o);
		}
		if (o instanceof ComplexEvent c) {
			return "**Complex event " + c.getName() + "**" + definition(o);
		}
		if (o instanceof Signal s) {
			StringBuilder text = new StringBuilder("**Signal " + s.getName() + "**: published to the run's signal topic");
			if (s.isHasUtility()) {
				text.append("; utility ").append(s.getUtility()).append(" in the score unless a test case says otherwise");
			}
			if (s.isTransition()) {
				text.append("; the ").append(s.isPerObject() ? "zone of one object near the robot" : "robot's zone")
						.append(" by ").append(s.getSource().getLiteral()).append(" goes from ")
						.append(s.getFrom().getLiteral()).append(" to ").append(s.getTo().getLiteral());
			}
			return text.toString();
		}
		return null;
	}

	/** The element as written in its file, so a hover on a use shows its declaration. */
	private static String definition(EObject o) {
		ICompositeNode node = NodeModelUtils.findActualNodeFor(o);
		if (node == null) {
			return "";
		}
		String text = NodeModelUtils.getTokenText(node);
		return "\n\n```vepl\n" + text + "\n```";
	}
}
