// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.lsp;

import java.io.File;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;

import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CompletionCapabilities;
import org.eclipse.lsp4j.DefinitionCapabilities;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.DidCloseTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DidSaveTextDocumentParams;
import org.eclipse.lsp4j.DocumentSymbolCapabilities;
import org.eclipse.lsp4j.FileEvent;
import org.eclipse.lsp4j.HoverCapabilities;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.PublishDiagnosticsCapabilities;
import org.eclipse.lsp4j.SynchronizationCapabilities;
import org.eclipse.lsp4j.TextDocumentClientCapabilities;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.WorkspaceFolder;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageServer;
import org.rei.eclipse.ReiPlugin;

/**
 * REI's language server as a child process of the workbench, spoken to over stdio with LSP4J.
 *
 * <p>Every message goes through one thread, in the order it was sent, after the server's initialisation: a change
 * of a document is never overtaken by the completion request typed right after it. A server that died is started
 * again on the next message, and the open documents are opened in it again.
 */
public final class LanguageServerConnection {
	/** How long the UI waits for an answer (completion, hover) before it gives up on this one. */
	public static final long ANSWER_MILLIS = 5_000;

	private final File log;
	private final ExecutorService queue = Executors.newSingleThreadExecutor(runnable -> {
		Thread thread = new Thread(runnable, "REI language server");
		thread.setDaemon(true);
		return thread;
	});
	private final ReiLanguageClient client = new ReiLanguageClient();
	/** uri -> the open document's state (text, version, how many editors show it). */
	private final Map<String, OpenDocument> open = new HashMap<>();
	private Process process;
	private LanguageServer server;
	/** When the server last failed to start: it is not tried again for a while, one failure is one log entry. */
	private long failedAt = Long.MIN_VALUE;
	private static final long RETRY_NANOS = 30_000_000_000L;

	private record OpenDocument(String languageId, String text, int version, int editors) {
	}

	private LanguageServerConnection(File log) {
		this.log = log;
	}

	public static LanguageServerConnection start(File log) {
		LanguageServerConnection connection = new LanguageServerConnection(log);
		connection.queue.execute(connection::ensureStarted);
		return connection;
	}

	// -- documents ------------------------------------------------------------------------------------------------

	public void didOpen(String uri, String text) {
		send(server -> {
			OpenDocument known = open.get(uri);
			if (known != null) {
				open.put(uri, new OpenDocument(known.languageId, known.text, known.version, known.editors + 1));
				return;
			}
			open.put(uri, new OpenDocument(Documents.languageOf(uri), text, 1, 1));
			server.getTextDocumentService().didOpen(
					new DidOpenTextDocumentParams(new TextDocumentItem(uri, Documents.languageOf(uri), 1, text)));
		});
	}

	public void didChange(String uri, String text) {
		send(server -> {
			OpenDocument known = open.get(uri);
			if (known == null || known.text.equals(text)) {
				return;
			}
			int version = known.version + 1;
			open.put(uri, new OpenDocument(known.languageId, text, version, known.editors));
			server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(
					new VersionedTextDocumentIdentifier(uri, version), List.of(new TextDocumentContentChangeEvent(text))));
		});
	}

	public void didSave(String uri) {
		send(server -> {
			if (open.containsKey(uri)) {
				server.getTextDocumentService().didSave(new DidSaveTextDocumentParams(new TextDocumentIdentifier(uri)));
			}
		});
	}

	public void didClose(String uri) {
		send(server -> {
			OpenDocument known = open.get(uri);
			if (known == null) {
				return;
			}
			if (known.editors > 1) {
				open.put(uri, new OpenDocument(known.languageId, known.text, known.version, known.editors - 1));
				return;
			}
			open.remove(uri);
			server.getTextDocumentService().didClose(new DidCloseTextDocumentParams(new TextDocumentIdentifier(uri)));
		});
	}

	/** Files changed on disk (not through an editor): the server re-validates them and their dependants. */
	public void filesChanged(List<FileEvent> events) {
		if (!events.isEmpty()) {
			send(server -> server.getWorkspaceService().didChangeWatchedFiles(new DidChangeWatchedFilesParams(events)));
		}
	}

	// -- requests -------------------------------------------------------------------------------------------------

	/** A request, sent after everything sent before it; the answer's future completes on LSP4J's thread. */
	public <T> CompletableFuture<T> request(Function<LanguageServer, CompletableFuture<T>> request) {
		CompletableFuture<T> answer = new CompletableFuture<>();
		queue.execute(() -> {
			try {
				ensureStarted();
				request.apply(server).whenComplete((value, error) -> {
					if (error != null) {
						answer.completeExceptionally(error);
					} else {
						answer.complete(value);
					}
				});
			} catch (RuntimeException error) {
				answer.completeExceptionally(error);
			}
		});
		return answer;
	}

	// -- the process ----------------------------------------------------------------------------------------------

	private interface Message {
		void send(LanguageServer server);
	}

	private void send(Message message) {
		queue.execute(() -> {
			try {
				ensureStarted();
				message.send(server);
			} catch (RuntimeException error) {
				ReiPlugin.log("REI language server: a message could not be sent", error);
			}
		});
	}

	/** On the queue's thread only. */
	private void ensureStarted() {
		if (process != null && process.isAlive()) {
			return;
		}
		if (failedAt != Long.MIN_VALUE && System.nanoTime() - failedAt < RETRY_NANOS) {
			throw new IllegalStateException("REI language server is not running (it failed to start; see " + log + ")");
		}
		boolean restart = process != null;
		try {
			Path jar = Jars.locate(Jars.LANGUAGE_SERVER);
			process = new ProcessBuilder(Jars.java(), "-jar", jar.toString())
					.redirectError(ProcessBuilder.Redirect.appendTo(log)).start();
			Launcher<LanguageServer> launcher = LSPLauncher.createClientLauncher(client, process.getInputStream(),
					process.getOutputStream());
			launcher.startListening();
			server = launcher.getRemoteProxy();
			server.initialize(initializeParams()).get(60, TimeUnit.SECONDS);
			server.initialized(new InitializedParams());
			if (restart) {
				ReiPlugin.info("REI language server restarted; its errors are in " + log);
				for (Map.Entry<String, OpenDocument> document : open.entrySet()) {
					OpenDocument state = document.getValue();
					server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(
							document.getKey(), state.languageId, state.version, state.text)));
				}
			}
		} catch (Exception error) {
			if (process != null) {
				process.destroyForcibly();
			}
			failedAt = System.nanoTime();
			throw new IllegalStateException("REI language server did not start (" + error.getMessage()
					+ "); its output is in " + log, error);
		}
	}

	private static InitializeParams initializeParams() {
		InitializeParams params = new InitializeParams();
		params.setProcessId((int) ProcessHandle.current().pid());
		// The workspace's folder: the server indexes every .rei and .vepl in it, so files that are not open get
		// markers as well, and cross-file references (imported catalogues) resolve.
		String root = Documents.uriOf(ResourcesPlugin.getWorkspace().getRoot().getLocation().toFile().toPath());
		params.setRootUri(root); // Xtext's server reads the root, not the folders
		params.setWorkspaceFolders(List.of(new WorkspaceFolder(root, "workspace")));
		TextDocumentClientCapabilities text = new TextDocumentClientCapabilities();
		text.setSynchronization(new SynchronizationCapabilities(false, false, true));
		text.setCompletion(new CompletionCapabilities());
		text.setHover(new HoverCapabilities(List.of(MarkupKind.PLAINTEXT, MarkupKind.MARKDOWN), false));
		text.setDefinition(new DefinitionCapabilities());
		DocumentSymbolCapabilities symbols = new DocumentSymbolCapabilities();
		symbols.setHierarchicalDocumentSymbolSupport(true);
		text.setDocumentSymbol(symbols);
		text.setPublishDiagnostics(new PublishDiagnosticsCapabilities());
		params.setCapabilities(new ClientCapabilities(null, text, null));
		return params;
	}

	/** Shut the server down politely, then for sure. */
	public void shutdown() {
		queue.execute(() -> {
			if (server != null && process != null && process.isAlive()) {
				try {
					server.shutdown().get(2, TimeUnit.SECONDS);
					server.exit();
				} catch (Exception ignored) {
					// a server that does not answer is stopped below
				}
			}
		});
		queue.shutdown();
		try {
			queue.awaitTermination(3, TimeUnit.SECONDS);
		} catch (InterruptedException interrupted) {
			Thread.currentThread().interrupt();
		}
		if (process != null) {
			process.destroy();
			try {
				if (!process.waitFor(2, TimeUnit.SECONDS)) {
					process.destroyForcibly();
				}
			} catch (InterruptedException interrupted) {
				process.destroyForcibly();
				Thread.currentThread().interrupt();
			}
		}
	}
}
