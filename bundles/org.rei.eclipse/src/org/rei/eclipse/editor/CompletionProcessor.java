// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.editor;

import java.util.List;

import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.contentassist.CompletionProposal;
import org.eclipse.jface.text.contentassist.ICompletionProposal;
import org.eclipse.jface.text.contentassist.IContentAssistProcessor;
import org.eclipse.jface.text.contentassist.IContextInformation;
import org.eclipse.jface.text.contentassist.IContextInformationValidator;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.TextEdit;
import org.rei.eclipse.ReiPlugin;
import org.rei.eclipse.lsp.Documents;

/** Content assist from the server's completion: floor, type, event and query names, keywords. */
public final class CompletionProcessor implements IContentAssistProcessor {
	private static final ICompletionProposal[] NONE = {};

	@Override
	public ICompletionProposal[] computeCompletionProposals(ITextViewer viewer, int offset) {
		IDocument document = viewer.getDocument();
		return Editors.placeOf(document, offset)
				.flatMap(place -> Editors.await(ReiPlugin.get().server().request(server -> server
						.getTextDocumentService().completion(new CompletionParams(place.document(), place.position())))))
				.map(answer -> proposals(document, offset, answer.isLeft() ? answer.getLeft() : answer.getRight().getItems()))
				.orElse(NONE);
	}

	private static ICompletionProposal[] proposals(IDocument document, int offset, List<CompletionItem> items) {
		int prefixStart = offset;
		try {
			while (prefixStart > 0 && Character.isJavaIdentifierPart(document.getChar(prefixStart - 1))) {
				prefixStart--;
			}
		} catch (org.eclipse.jface.text.BadLocationException outside) {
			prefixStart = offset;
		}
		int wordStart = prefixStart;
		String prefix = document.get().substring(wordStart, offset).toLowerCase(java.util.Locale.ROOT);
		// The client filters by what was typed, as LSP clients do: the server also proposes what may follow
		// (a closing brace), which would replace the typed word.
		return items.stream()
				.filter(item -> (item.getFilterText() != null ? item.getFilterText() : item.getLabel())
						.toLowerCase(java.util.Locale.ROOT).startsWith(prefix))
				.map(item -> proposal(document, offset, wordStart, item)).toArray(ICompletionProposal[]::new);
	}

	private static ICompletionProposal proposal(IDocument document, int offset, int wordStart, CompletionItem item) {
		String text = item.getInsertText() != null ? item.getInsertText() : item.getLabel();
		int start = wordStart;
		int end = offset;
		if (item.getTextEdit() != null && item.getTextEdit().isLeft()) {
			TextEdit textEdit = item.getTextEdit().getLeft();
			int[] offsets = Documents.offsetsOf(document, textEdit.getRange());
			start = offsets[0];
			end = Math.max(offsets[1], offset);
			text = textEdit.getNewText();
		} else if (item.getTextEdit() != null && item.getTextEdit().isRight()) {
			int[] offsets = Documents.offsetsOf(document, item.getTextEdit().getRight().getReplace());
			start = offsets[0];
			end = Math.max(offsets[1], offset);
			text = item.getTextEdit().getRight().getNewText();
		}
		String display = item.getDetail() == null || item.getDetail().isBlank() ? item.getLabel()
				: item.getLabel() + " - " + item.getDetail();
		String documentation = item.getDocumentation() == null ? null
				: item.getDocumentation().isLeft() ? item.getDocumentation().getLeft()
						: item.getDocumentation().getRight().getValue();
		return new CompletionProposal(text, start, end - start, text.length(), null, display, null, documentation);
	}

	@Override
	public IContextInformation[] computeContextInformation(ITextViewer viewer, int offset) {
		return null;
	}

	@Override
	public char[] getCompletionProposalAutoActivationCharacters() {
		return new char[] { '.' };
	}

	@Override
	public char[] getContextInformationAutoActivationCharacters() {
		return null;
	}

	@Override
	public String getErrorMessage() {
		return null;
	}

	@Override
	public IContextInformationValidator getContextInformationValidator() {
		return null;
	}
}
