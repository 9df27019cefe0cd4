// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.editor;

import java.util.Optional;

import org.eclipse.jface.text.DocumentEvent;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IDocumentListener;
import org.eclipse.jface.text.ITextInputListener;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.reconciler.IReconciler;
import org.eclipse.jface.text.reconciler.IReconcilingStrategy;
import org.rei.eclipse.ReiPlugin;
import org.rei.eclipse.lsp.Documents;

/**
 * Keeps the language server's copy of an editor's text current: open when the editor gets its document, every
 * change as it happens (the server debounces its own validation), close with the editor.
 *
 * <p>It is the Generic Editor's reconciler for REI's content types: the one hook the editor gives per viewer.
 */
public final class DocumentSync implements IReconciler, ITextInputListener, IDocumentListener {
	private ITextViewer viewer;
	private IDocument document;
	private String uri;

	@Override
	public void install(ITextViewer textViewer) {
		viewer = textViewer;
		viewer.addTextInputListener(this);
		connect(viewer.getDocument());
	}

	@Override
	public void uninstall() {
		if (viewer != null) {
			viewer.removeTextInputListener(this);
		}
		disconnect();
		viewer = null;
	}

	@Override
	public void inputDocumentAboutToBeChanged(IDocument oldInput, IDocument newInput) {
		disconnect();
	}

	@Override
	public void inputDocumentChanged(IDocument oldInput, IDocument newInput) {
		connect(newInput);
	}

	@Override
	public void documentAboutToBeChanged(DocumentEvent event) {
	}

	@Override
	public void documentChanged(DocumentEvent event) {
		ReiPlugin.get().server().didChange(uri, event.getDocument().get());
	}

	private void connect(IDocument newDocument) {
		if (newDocument == null || newDocument == document) {
			return;
		}
		Optional<String> location = Documents.uriOf(newDocument);
		if (location.isEmpty()) {
			return; // not a file (a compare editor's side, a remote file): nothing the server can resolve
		}
		document = newDocument;
		uri = location.get();
		document.addDocumentListener(this);
		ReiPlugin.get().server().didOpen(uri, document.get());
	}

	private void disconnect() {
		if (document == null) {
			return;
		}
		document.removeDocumentListener(this);
		ReiPlugin.get().server().didClose(uri);
		document = null;
		uri = null;
	}

	@Override
	public IReconcilingStrategy getReconcilingStrategy(String contentType) {
		return null;
	}
}
