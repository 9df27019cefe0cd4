// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.commands;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;

/** Right-click > REI > Generate artifacts, on a .rei file or in its editor. */
public final class GenerateHandler extends AbstractHandler {
	@Override
	public Object execute(ExecutionEvent event) throws ExecutionException {
		new GenerateJob(Selections.testCaseOf(event)
				.orElseThrow(() -> new ExecutionException("Generate artifacts needs a .rei file selected or open")))
				.schedule();
		return null;
	}
}
