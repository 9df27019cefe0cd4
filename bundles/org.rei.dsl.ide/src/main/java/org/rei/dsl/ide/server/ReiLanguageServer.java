/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.ide.server;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.stream.Stream;

import org.apache.log4j.ConsoleAppender;
import org.apache.log4j.Level;
import org.apache.log4j.Logger;
import org.apache.log4j.PatternLayout;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.WorkspaceFolder;
import org.eclipse.xtext.ide.server.LanguageServerImpl;

/**
 * Xtext's server fails {@code initialize} with a NullPointerException when the client names no root (no
 * {@code rootUri}, no {@code rootPath}): VS Code opening a single file without a folder, or a client that sends only
 * {@code workspaceFolders}. The first workspace folder is then the root, else an empty temporary folder of the
 * session's own, deleted at exit: it costs no indexing, and files outside the root are checked as always, their
 * catalogue imports resolved relative to themselves.
 */
public class ReiLanguageServer extends LanguageServerImpl {

	static {
		// Xtext's log4j.properties logs to stdout, which the launcher silences (stdout carries the protocol):
		// warnings and errors (a file the server could not check among them) go to stderr, the server log of editors
		ConsoleAppender stderr = new ConsoleAppender(new PatternLayout("%d{ISO8601} %-5p %c{1} - %m%n"),
				ConsoleAppender.SYSTEM_ERR);
		stderr.setThreshold(Level.WARN);
		Logger.getRootLogger().addAppender(stderr);
	}

	@Override
	@SuppressWarnings("deprecation") // rootPath: old clients still send only it, and Xtext reads it
	public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
		if (params.getRootUri() == null && params.getRootPath() == null) {
			List<WorkspaceFolder> folders = params.getWorkspaceFolders();
			params.setRootUri(folders != null && !folders.isEmpty() ? folders.get(0).getUri() : emptyRoot());
		}
		return super.initialize(params);
	}

	private static String emptyRoot() {
		try {
			Path root = Files.createTempDirectory("rei-language-server-");
			Runtime.getRuntime().addShutdownHook(new Thread(() -> delete(root)));
			return root.toUri().toString();
		} catch (IOException e) {
			throw new UncheckedIOException("cannot create the language server's empty root", e);
		}
	}

	private static void delete(Path root) {
		try (Stream<Path> paths = Files.walk(root)) {
			paths.sorted(Comparator.reverseOrder()).forEach(path -> path.toFile().delete());
		} catch (IOException e) {
			// best effort at exit: a leftover empty folder in the temporary directory harms no one
		}
	}
}
