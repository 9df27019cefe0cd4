// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.lsp;

import java.io.File;
import java.io.IOException;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.core.runtime.FileLocator;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.rei.eclipse.ReiIds;

/** The two jars the plug-in ships (built by REI's main Maven build) and the Java that runs them. */
public final class Jars {
	public static final String LANGUAGE_SERVER = "server/rei-language-server.jar";
	public static final String GENERATOR = "server/rei-cli.jar";

	private Jars() {
	}

	/** The jar on disk; installed bundles are unpacked jars or folders, FileLocator extracts when needed. */
	public static Path locate(String entry) throws IOException {
		URL url = FileLocator.find(Platform.getBundle(ReiIds.PLUGIN), new org.eclipse.core.runtime.Path(entry));
		if (url == null) {
			throw new IOException("the REI plug-in has no " + entry + " (a plug-in built without REI's jars)");
		}
		return new File(FileLocator.toFileURL(url).getPath()).toPath();
	}

	/**
	 * The java executable: the preference when set, else the one running the workbench (REI's jars need Java 17,
	 * the workbench already runs on 21 or later).
	 */
	public static String java() {
		String configured = InstanceScope.INSTANCE.getNode(ReiIds.PLUGIN).get(ReiIds.PREF_JAVA, "").strip();
		if (!configured.isEmpty()) {
			return configured;
		}
		Path own = Path.of(System.getProperty("java.home"), "bin", "java");
		return Files.isExecutable(own) ? own.toString() : "java";
	}
}
