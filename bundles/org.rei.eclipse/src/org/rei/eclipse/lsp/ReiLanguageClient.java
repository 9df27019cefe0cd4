// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.lsp;

import java.util.concurrent.CompletableFuture;

import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.services.LanguageClient;
import org.rei.eclipse.ReiPlugin;

/** What the server tells the workbench: diagnostics become problem markers, messages go to the error log. */
final class ReiLanguageClient implements LanguageClient {
	@Override
	public void publishDiagnostics(PublishDiagnosticsParams diagnostics) {
		Markers.update(diagnostics.getUri(), diagnostics.getDiagnostics());
	}

	@Override
	public void logMessage(MessageParams message) {
		if (message.getType() == MessageType.Error) {
			ReiPlugin.log("REI language server: " + message.getMessage(), null);
		}
	}

	@Override
	public void showMessage(MessageParams message) {
		logMessage(message);
	}

	@Override
	public CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams request) {
		logMessage(new MessageParams(request.getType(), request.getMessage()));
		return CompletableFuture.completedFuture(null);
	}

	@Override
	public void telemetryEvent(Object object) {
		// REI's server sends none; nothing is collected
	}
}
