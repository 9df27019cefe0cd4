// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.editor;

import java.util.stream.Collectors;

import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.ITextHover;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.Region;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.rei.eclipse.ReiPlugin;

/** The server's hover as plain text: a floor's extent, a type's shape and mass, an event's definition. */
public final class LspHover implements ITextHover {
	@Override
	public String getHoverInfo(ITextViewer viewer, IRegion region) {
		return Editors.placeOf(viewer.getDocument(), region.getOffset())
				.flatMap(place -> Editors.await(ReiPlugin.get().server().request(server -> server
						.getTextDocumentService().hover(new HoverParams(place.document(), place.position())))))
				.map(LspHover::textOf).filter(text -> !text.isBlank()).orElse(null);
	}

	static String textOf(Hover hover) {
		if (hover.getContents() == null) {
			return "";
		}
		if (hover.getContents().isRight()) {
			MarkupContent content = hover.getContents().getRight();
			return MarkupKind.MARKDOWN.equals(content.getKind()) ? plain(content.getValue()) : content.getValue();
		}
		return hover.getContents().getLeft().stream()
				.map(part -> plain(part.isLeft() ? part.getLeft() : part.getRight().getValue()))
				.collect(Collectors.joining("\n\n"));
	}

	/** The default hover shows text: the emphasis and code marks of the server's markdown would show as is. */
	static String plain(String markdown) {
		return markdown.replace("**", "").replace("`", "");
	}

	@Override
	public IRegion getHoverRegion(ITextViewer viewer, int offset) {
		return new Region(offset, 0);
	}
}
