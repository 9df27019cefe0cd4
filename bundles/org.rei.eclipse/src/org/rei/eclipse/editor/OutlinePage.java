// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.editor;

import java.util.List;

import org.eclipse.jface.text.DocumentEvent;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IDocumentListener;
import org.eclipse.jface.viewers.ITreeContentProvider;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.LabelProvider;
import org.eclipse.jface.viewers.TreeViewer;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.texteditor.ITextEditor;
import org.eclipse.ui.views.contentoutline.ContentOutlinePage;
import org.rei.eclipse.ReiPlugin;
import org.rei.eclipse.lsp.Documents;

/** The Outline view of a .rei or .vepl editor: the server's document symbols, refreshed as the text changes. */
final class OutlinePage extends ContentOutlinePage implements IDocumentListener {
	private static final int REFRESH_DELAY_MILLIS = 500;
	private final ITextEditor editor;
	private final IDocument document;
	private final Runnable refresh = this::refresh;

	OutlinePage(ITextEditor editor) {
		this.editor = editor;
		this.document = editor.getDocumentProvider().getDocument(editor.getEditorInput());
	}

	@Override
	public void createControl(Composite parent) {
		super.createControl(parent);
		TreeViewer viewer = getTreeViewer();
		viewer.setContentProvider(new SymbolContent());
		viewer.setLabelProvider(new LabelProvider() {
			@Override
			public String getText(Object element) {
				DocumentSymbol symbol = (DocumentSymbol) element;
				return symbol.getDetail() == null || symbol.getDetail().isBlank() ? symbol.getName()
						: symbol.getName() + " : " + symbol.getDetail();
			}
		});
		viewer.addSelectionChangedListener(event -> {
			if (event.getSelection() instanceof IStructuredSelection selection
					&& selection.getFirstElement() instanceof DocumentSymbol symbol) {
				int[] offsets = Documents.offsetsOf(document, symbol.getSelectionRange());
				editor.selectAndReveal(offsets[0], offsets[1] - offsets[0]);
			}
		});
		if (document != null) {
			document.addDocumentListener(this);
		}
		refresh();
	}

	@Override
	public void dispose() {
		if (document != null) {
			document.removeDocumentListener(this);
		}
		super.dispose();
	}

	@Override
	public void documentAboutToBeChanged(DocumentEvent event) {
	}

	@Override
	public void documentChanged(DocumentEvent event) {
		// one refresh after a burst of typing; a document may also change off the UI thread (a file buffer's sync)
		Display.getDefault().asyncExec(() -> Display.getDefault().timerExec(REFRESH_DELAY_MILLIS, refresh));
	}

	private void refresh() {
		String uri = document == null ? null : Documents.uriOf(document).orElse(null);
		if (uri == null) {
			return;
		}
		ReiPlugin.get().server()
				.request(server -> server.getTextDocumentService()
						.documentSymbol(new DocumentSymbolParams(new TextDocumentIdentifier(uri))))
				.thenAccept(answer -> {
					List<DocumentSymbol> symbols = answer.stream().filter(either -> either.isRight())
							.map(either -> either.getRight()).toList();
					Display.getDefault().asyncExec(() -> {
						TreeViewer viewer = getTreeViewer();
						if (viewer != null && !viewer.getControl().isDisposed()) {
							viewer.setInput(symbols);
							viewer.expandToLevel(2);
						}
					});
				});
	}

	private static final class SymbolContent implements ITreeContentProvider {
		@Override
		public Object[] getElements(Object input) {
			return ((List<?>) input).toArray();
		}

		@Override
		public Object[] getChildren(Object parent) {
			List<DocumentSymbol> children = ((DocumentSymbol) parent).getChildren();
			return children == null ? new Object[0] : children.toArray();
		}

		@Override
		public Object getParent(Object element) {
			return null;
		}

		@Override
		public boolean hasChildren(Object element) {
			List<DocumentSymbol> children = ((DocumentSymbol) element).getChildren();
			return children != null && !children.isEmpty();
		}
	}
}
