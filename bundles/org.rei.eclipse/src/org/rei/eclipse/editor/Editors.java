// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.editor;

import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.eclipse.jface.text.BadLocationException;
import org.eclipse.jface.text.IDocument;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.rei.eclipse.ReiPlugin;
import org.rei.eclipse.lsp.Documents;
import org.rei.eclipse.lsp.LanguageServerConnection;

/** What the editor features share: where in which file a request is, and waiting for its answer. */
final class Editors {
	private Editors() {
	}

	record Place(TextDocumentIdentifier document, Position position) {
	}

	static Optional<Place> placeOf(IDocument document, int offset) {
		if (document == null) {
			return Optional.empty();
		}
		try {
			Position position = Documents.positionOf(document, offset);
			return Documents.uriOf(document).filter(Documents::isReiSource)
					.map(uri -> new Place(new TextDocumentIdentifier(uri), position));
		} catch (BadLocationException outside) {
			return Optional.empty();
		}
	}

	/** The answer, or empty when the server took too long or failed (the editor stays responsive). */
	static <T> Optional<T> await(CompletableFuture<T> answer) {
		try {
			return Optional.ofNullable(answer.get(LanguageServerConnection.ANSWER_MILLIS, TimeUnit.MILLISECONDS));
		} catch (InterruptedException interrupted) {
			Thread.currentThread().interrupt();
			return Optional.empty();
		} catch (java.util.concurrent.TimeoutException slow) {
			return Optional.empty(); // a busy server: the user asks again
		} catch (Exception failed) {
			if (!(failed.getCause() instanceof IllegalStateException)) { // a server that failed to start is logged once
				ReiPlugin.log("REI language server: no answer", failed);
			}
			return Optional.empty();
		}
	}
}
