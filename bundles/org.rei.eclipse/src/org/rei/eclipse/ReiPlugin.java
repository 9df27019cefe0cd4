// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.ui.plugin.AbstractUIPlugin;
import org.osgi.framework.BundleContext;
import org.rei.eclipse.commands.GenerateOnSave;
import org.rei.eclipse.lsp.FileWatcher;
import org.rei.eclipse.lsp.LanguageServerConnection;

/** The bundle's life: one language server for the workbench, started on first use and stopped with the bundle. */
public final class ReiPlugin extends AbstractUIPlugin {
	private static ReiPlugin instance;
	private LanguageServerConnection server;
	private GenerateOnSave generateOnSave;
	private FileWatcher fileWatcher;

	public static ReiPlugin get() {
		return instance;
	}

	@Override
	public void start(BundleContext context) throws Exception {
		super.start(context);
		instance = this;
		generateOnSave = GenerateOnSave.install();
	}

	@Override
	public void stop(BundleContext context) throws Exception {
		try {
			generateOnSave.uninstall();
			LanguageServerConnection running;
			synchronized (this) {
				running = server;
				server = null;
			}
			if (running != null) {
				fileWatcher.uninstall();
				running.shutdown();
			}
		} finally {
			instance = null;
			super.stop(context);
		}
	}

	/** The workbench's language server connection; the process starts in the background on the first call. */
	public synchronized LanguageServerConnection server() {
		if (server == null) {
			server = LanguageServerConnection.start(getStateLocation().append("language-server.log").toFile());
			fileWatcher = FileWatcher.install(server);
		}
		return server;
	}

	public static void log(String message, Throwable error) {
		ILog.of(ReiPlugin.class).log(new Status(IStatus.ERROR, ReiIds.PLUGIN, message, error));
	}

	public static void info(String message) {
		ILog.of(ReiPlugin.class).log(new Status(IStatus.INFO, ReiIds.PLUGIN, message));
	}
}
