/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.ide;

import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.rei.vepl.ide.contentassist.VeplProposalProvider;

/** Bindings of VEPL's editor services beyond the generated defaults. */
public class VeplIdeModule extends AbstractVeplIdeModule {

	/** Completion of query and mission event names, which the grammar only knows as IDs. */
	public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
		return VeplProposalProvider.class;
	}
}
