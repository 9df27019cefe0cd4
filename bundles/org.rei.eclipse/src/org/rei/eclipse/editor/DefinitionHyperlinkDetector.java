// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.editor;

import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.Region;
import org.eclipse.jface.text.hyperlink.AbstractHyperlinkDetector;
import org.eclipse.jface.text.hyperlink.IHyperlink;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.Range;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.texteditor.ITextEditor;
import org.rei.eclipse.ReiPlugin;
import org.rei.eclipse.lsp.Documents;

/** Ctrl+click on a name goes to its definition (a floor, a type, an event), in this file or an imported one. */
public final class DefinitionHyperlinkDetector extends AbstractHyperlinkDetector {
	@Override
	public IHyperlink[] detectHyperlinks(ITextViewer viewer, IRegion region, boolean canShowMultipleHyperlinks) {
		IDocument document = viewer.getDocument();
		List<Target> targets = Editors.placeOf(document, region.getOffset())
				.flatMap(place -> Editors.await(ReiPlugin.get().server().request(server -> server
						.getTextDocumentService().definition(new DefinitionParams(place.document(), place.position())))))
				.map(answer -> answer.isLeft()
						? answer.getLeft().stream().map(Target::of).toList()
						: answer.getRight().stream().map(Target::of).toList())
				.orElse(List.of());
		if (targets.isEmpty()) {
			return null;
		}
		IRegion word = wordAt(document, region.getOffset());
		return targets.stream().map(target -> new Link(word, target)).toArray(IHyperlink[]::new);
	}

	private static IRegion wordAt(IDocument document, int offset) {
		try {
			int start = offset;
			int end = offset;
			while (start > 0 && Character.isJavaIdentifierPart(document.getChar(start - 1))) {
				start--;
			}
			while (end < document.getLength() && Character.isJavaIdentifierPart(document.getChar(end))) {
				end++;
			}
			return new Region(start, end - start);
		} catch (org.eclipse.jface.text.BadLocationException outside) {
			return new Region(offset, 0);
		}
	}

	private record Target(String uri, Range range) {
		static Target of(Location location) {
			return new Target(location.getUri(), location.getRange());
		}

		static Target of(LocationLink link) {
			return new Target(link.getTargetUri(), link.getTargetSelectionRange());
		}
	}

	private record Link(IRegion region, Target target) implements IHyperlink {
		@Override
		public IRegion getHyperlinkRegion() {
			return region;
		}

		@Override
		public String getTypeLabel() {
			return "Definition";
		}

		@Override
		public String getHyperlinkText() {
			return "Open Definition";
		}

		@Override
		public void open() {
			IFile file = Documents.fileOf(target.uri).orElse(null);
			if (file == null) {
				return;
			}
			try {
				IEditorPart editor = IDE.openEditor(
						PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage(), file);
				if (editor instanceof ITextEditor text) {
					IDocument document = text.getDocumentProvider().getDocument(text.getEditorInput());
					int[] offsets = Documents.offsetsOf(document, target.range);
					text.selectAndReveal(offsets[0], offsets[1] - offsets[0]);
				}
			} catch (PartInitException failed) {
				ReiPlugin.log("cannot open " + file.getFullPath(), failed);
			}
		}
	}
}
