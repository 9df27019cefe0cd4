/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.ide.server;

import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.eclipse.xtext.ide.server.ServerLauncher;
import org.eclipse.xtext.ide.server.ServerModule;

import com.google.inject.util.Modules;

/** The main class of rei-language-server.jar: Xtext's launcher and server module, with {@link ReiLanguageServer}. */
public final class ReiServerLauncher {

	private ReiServerLauncher() {
	}

	public static void main(String[] args) {
		ServerLauncher.launch(ReiServerLauncher.class.getName(), args, Modules.override(new ServerModule())
				.with(binder -> binder.bind(LanguageServerImpl.class).to(ReiLanguageServer.class)));
		// launch returns when the client's end of stdin closes without an exit notification (an editor that
		// crashed or was killed); Xtext's worker threads would keep this JVM alive for ever, an orphan per crash.
		System.exit(0);
	}
}
