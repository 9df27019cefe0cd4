// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.lsp;

import java.net.URI;
import java.nio.file.Path;
import java.util.Optional;

import org.eclipse.core.filebuffers.FileBuffers;
import org.eclipse.core.filebuffers.ITextFileBuffer;
import org.eclipse.core.filebuffers.LocationKind;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.jface.text.BadLocationException;
import org.eclipse.jface.text.IDocument;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;

/** Documents, files and their LSP URIs and positions. */
public final class Documents {
	private Documents() {
	}

	/** The form the server uses: {@code file:///path}, so the URIs it sends back compare equal. */
	public static String uriOf(Path path) {
		return path.toAbsolutePath().normalize().toUri().toString();
	}

	public static Optional<String> uriOf(IDocument document) {
		ITextFileBuffer buffer = FileBuffers.getTextFileBufferManager().getTextFileBuffer(document);
		if (buffer == null || buffer.getFileStore() == null) {
			return Optional.empty();
		}
		URI location = buffer.getFileStore().toURI();
		return "file".equals(location.getScheme()) ? Optional.of(uriOf(Path.of(location))) : Optional.empty();
	}

	public static Optional<IFile> fileOf(String uri) {
		IFile[] files = ResourcesPlugin.getWorkspace().getRoot().findFilesForLocationURI(URI.create(uri));
		return files.length == 0 ? Optional.empty() : Optional.of(files[0]);
	}

	/** The open document of a workspace file, if an editor (a file buffer) has it. */
	public static Optional<IDocument> openDocument(IFile file) {
		ITextFileBuffer buffer = FileBuffers.getTextFileBufferManager().getTextFileBuffer(file.getFullPath(),
				LocationKind.IFILE);
		return buffer == null ? Optional.empty() : Optional.of(buffer.getDocument());
	}

	public static String languageOf(String uri) {
		return uri.endsWith(".vepl") ? "vepl" : "rei";
	}

	public static boolean isReiSource(String name) {
		return name.endsWith(".rei") || name.endsWith(".vepl");
	}

	public static Position positionOf(IDocument document, int offset) throws BadLocationException {
		int line = document.getLineOfOffset(offset);
		return new Position(line, offset - document.getLineOffset(line));
	}

	/** An LSP position as an offset, clamped into the document (the server may have seen an older text). */
	public static int offsetOf(IDocument document, Position position) {
		try {
			int line = Math.min(position.getLine(), document.getNumberOfLines() - 1);
			int lineOffset = document.getLineOffset(line);
			int lineLength = document.getLineLength(line);
			return lineOffset + Math.min(position.getCharacter(), lineLength);
		} catch (BadLocationException outside) {
			return document.getLength();
		}
	}

	public static int[] offsetsOf(IDocument document, Range range) {
		int start = offsetOf(document, range.getStart());
		return new int[] { start, Math.max(start, offsetOf(document, range.getEnd())) };
	}
}
