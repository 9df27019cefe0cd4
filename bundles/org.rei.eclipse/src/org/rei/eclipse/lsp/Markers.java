// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.lsp;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.Charset;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.jface.text.Document;
import org.eclipse.jface.text.IDocument;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.rei.eclipse.ReiIds;

/** The server's diagnostics of one file as its REI problem markers: all of them replaced at once. */
final class Markers {
	private Markers() {
	}

	static void update(String uri, List<Diagnostic> diagnostics) {
		Documents.fileOf(uri).ifPresent(file -> {
			WorkspaceJob job = new WorkspaceJob("REI problem markers of " + file.getName()) {
				@Override
				public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
					if (file.exists()) {
						replace(file, diagnostics);
					}
					return Status.OK_STATUS;
				}
			};
			job.setRule(file);
			job.setSystem(true);
			job.schedule();
		});
	}

	private static void replace(IFile file, List<Diagnostic> diagnostics) throws CoreException {
		file.deleteMarkers(ReiIds.PROBLEM_MARKER, false, IResource.DEPTH_ZERO);
		if (diagnostics.isEmpty()) {
			return;
		}
		IDocument document = Documents.openDocument(file).orElseGet(() -> read(file));
		for (Diagnostic diagnostic : diagnostics) {
			IMarker marker = file.createMarker(ReiIds.PROBLEM_MARKER);
			int[] offsets = Documents.offsetsOf(document, diagnostic.getRange());
			marker.setAttribute(IMarker.MESSAGE, diagnostic.getMessage().isLeft() ? diagnostic.getMessage().getLeft()
					: diagnostic.getMessage().getRight().getValue()); // LSP 3.18 allows a markup message
			marker.setAttribute(IMarker.SEVERITY, severityOf(diagnostic.getSeverity()));
			marker.setAttribute(IMarker.LINE_NUMBER, diagnostic.getRange().getStart().getLine() + 1);
			marker.setAttribute(IMarker.CHAR_START, offsets[0]);
			marker.setAttribute(IMarker.CHAR_END, offsets[1]);
			if (diagnostic.getCode() != null) {
				marker.setAttribute("code", diagnostic.getCode().get().toString());
			}
		}
	}

	private static IDocument read(IFile file) {
		try (InputStream in = file.getContents(true)) {
			return new Document(new String(in.readAllBytes(), Charset.forName(file.getCharset())));
		} catch (IOException | CoreException unreadable) {
			return new Document();
		}
	}

	private static int severityOf(DiagnosticSeverity severity) {
		if (severity == null) {
			return IMarker.SEVERITY_ERROR;
		}
		return switch (severity) {
		case Error -> IMarker.SEVERITY_ERROR;
		case Warning -> IMarker.SEVERITY_WARNING;
		default -> IMarker.SEVERITY_INFO;
		};
	}
}
