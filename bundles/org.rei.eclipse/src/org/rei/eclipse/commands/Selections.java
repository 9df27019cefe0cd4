// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.commands;

import java.util.Optional;

import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.Adapters;
import org.eclipse.jface.viewers.ISelection;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IFileEditorInput;
import org.eclipse.ui.handlers.HandlerUtil;

/** The .rei file a command is for: the one selected in a view, else the active editor's. */
final class Selections {
	private Selections() {
	}

	static Optional<IFile> testCaseOf(ExecutionEvent event) {
		ISelection selection = HandlerUtil.getCurrentSelection(event);
		if (selection instanceof IStructuredSelection structured && !structured.isEmpty()) {
			IFile file = Adapters.adapt(structured.getFirstElement(), IFile.class);
			if (file != null && file.getName().endsWith(".rei")) {
				return Optional.of(file);
			}
		}
		IEditorPart editor = HandlerUtil.getActiveEditor(event);
		if (editor != null && editor.getEditorInput() instanceof IFileEditorInput input
				&& input.getFile().getName().endsWith(".rei")) {
			return Optional.of(input.getFile());
		}
		return Optional.empty();
	}
}
