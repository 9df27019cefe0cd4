/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.ide.contentassist;

import java.util.Collection;
import java.util.TreeSet;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IIdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.rei.vepl.services.VeplGrammarAccess;
import org.rei.vepl.validation.KnownQueries;
import org.rei.vepl.validation.VeplValidator;
import org.rei.vepl.vepl.ComplexEvent;

import com.google.common.base.Predicate;
import com.google.inject.Inject;

/**
 * Completion of the two names the grammar can only call an ID: the query a query event names and the mission
 * event an atomic event names. Both lists are the validator's, so what is offered is exactly what it accepts.
 * Events, signals and keywords come from scoping and the grammar; only a complex event's own name is left out of
 * its definition, as the validator refuses a complex event that refers to itself.
 */
public class VeplProposalProvider extends IdeContentProposalProvider {

	@Inject
	private VeplGrammarAccess grammar;

	@Override
	protected void _createProposals(Assignment assignment, ContentAssistContext context,
			IIdeContentProposalAcceptor acceptor) {
		if (assignment == grammar.getQueryEventAccess().getQueryAssignment_4()) {
			propose(new TreeSet<>(KnownQueries.of(context.getResource())), "query", context, acceptor);
			return;
		} else if (assignment == grammar.getAtomicEventAccess().getMissionAssignment_5()) {
			propose(VeplValidator.MISSION_EVENTS, "mission event", context, acceptor);
			return;
		}
		super._createProposals(assignment, context, acceptor);
	}

	@Override
	protected Predicate<IEObjectDescription> getCrossrefFilter(CrossReference reference, ContentAssistContext context) {
		ComplexEvent defined = EcoreUtil2.getContainerOfType(context.getCurrentModel(), ComplexEvent.class);
		if (defined == null) {
			return super.getCrossrefFilter(reference, context);
		}
		URI self = EcoreUtil.getURI(defined);
		return d -> !self.equals(d.getEObjectURI());
	}

	private void propose(Collection<String> names, String description, ContentAssistContext context,
			IIdeContentProposalAcceptor acceptor) {
		for (String name : names) {
			ContentAssistEntry entry = getProposalCreator().createProposal(name, context, e -> {
				e.setDescription(description);
				e.setKind(ContentAssistEntry.KIND_VALUE);
			});
			if (entry != null) {
				acceptor.accept(entry, getProposalPriorities().getDefaultPriority(entry));
			}
		}
	}
}
