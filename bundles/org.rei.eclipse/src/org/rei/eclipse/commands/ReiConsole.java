// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.commands;

import java.io.IOException;

import org.eclipse.ui.console.ConsolePlugin;
import org.eclipse.ui.console.IConsole;
import org.eclipse.ui.console.IConsoleManager;
import org.eclipse.ui.console.MessageConsole;
import org.eclipse.ui.console.MessageConsoleStream;

/** The "REI" console: what the generator and rei run print, as they print it. */
final class ReiConsole {
	private static final String NAME = "REI";

	private ReiConsole() {
	}

	static void println(String line) {
		try (MessageConsoleStream stream = console().newMessageStream()) {
			stream.println(line);
		} catch (IOException closed) {
			// the console was closed: the job's status still reports the outcome
		}
	}

	static MessageConsole console() {
		IConsoleManager consoles = ConsolePlugin.getDefault().getConsoleManager();
		for (IConsole existing : consoles.getConsoles()) {
			if (NAME.equals(existing.getName()) && existing instanceof MessageConsole message) {
				return message;
			}
		}
		MessageConsole created = new MessageConsole(NAME, null);
		consoles.addConsoles(new IConsole[] { created });
		return created;
	}
}
