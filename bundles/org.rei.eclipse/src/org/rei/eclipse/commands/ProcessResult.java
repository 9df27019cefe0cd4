// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.commands;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/** A finished child process: its exit code and its output (standard output and error, interleaved). */
public record ProcessResult(int exitCode, String output) {
	/** The code of a process REI stopped: it hung past its time, or the user cancelled it. */
	public static final int STOPPED = -1;

	/**
	 * Runs a command to its end. Each output line goes to {@code lines} as it comes (may be null); a command still
	 * running after {@code timeoutSeconds} is killed with its children, so a hung tool never hangs the workbench.
	 */
	public static ProcessResult run(List<String> command, File directory, long timeoutSeconds, Consumer<String> lines)
			throws IOException, InterruptedException {
		return run(command, directory, timeoutSeconds, lines, () -> false);
	}

	public static ProcessResult run(List<String> command, File directory, long timeoutSeconds, Consumer<String> lines,
			BooleanSupplier cancelled) throws IOException, InterruptedException {
		Process process = new ProcessBuilder(command).directory(directory).redirectErrorStream(true).start();
		process.getOutputStream().close(); // nothing to read: a tool that asks gets end of input, not a hang
		StringBuilder output = new StringBuilder();
		Thread reader = new Thread(() -> {
			try (BufferedReader in = new BufferedReader(
					new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
				for (String line = in.readLine(); line != null; line = in.readLine()) {
					synchronized (output) {
						output.append(line).append('\n');
					}
					if (lines != null) {
						lines.accept(line);
					}
				}
			} catch (IOException closed) {
				// the process ended or was killed
			}
		}, "REI process output");
		reader.setDaemon(true);
		reader.start();
		long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(timeoutSeconds);
		while (!process.waitFor(100, TimeUnit.MILLISECONDS)) {
			if (cancelled.getAsBoolean() || System.nanoTime() > deadline) {
				process.descendants().forEach(ProcessHandle::destroy);
				process.destroy();
				if (!process.waitFor(5, TimeUnit.SECONDS)) {
					process.descendants().forEach(ProcessHandle::destroyForcibly);
					process.destroyForcibly();
				}
				reader.join(1000);
				synchronized (output) {
					return new ProcessResult(STOPPED, output + (cancelled.getAsBoolean() ? "(cancelled)\n"
							: "(stopped after " + timeoutSeconds + " s)\n"));
				}
			}
		}
		reader.join(5000);
		synchronized (output) {
			return new ProcessResult(process.exitValue(), output.toString());
		}
	}
}
