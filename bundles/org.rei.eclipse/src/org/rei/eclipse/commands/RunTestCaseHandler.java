// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.commands;

import java.io.IOException;
import java.net.MalformedURLException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.PlatformUI;
import org.rei.eclipse.ReiIds;
import org.rei.eclipse.ReiPlugin;

/**
 * Right-click > REI > Run test case: {@code rei run FILE -o OUT} with the user's REI installation (the simulation,
 * router and monitor are REI's, not the plug-in's), its output in the REI console, then the report in a browser.
 */
public final class RunTestCaseHandler extends AbstractHandler {
	/** A run is a simulation plus its monitoring: far longer than a generation, still never forever. */
	private static final long TIMEOUT_SECONDS = 3600;

	@Override
	public Object execute(ExecutionEvent event) throws ExecutionException {
		IFile testCase = Selections.testCaseOf(event)
				.orElseThrow(() -> new ExecutionException("Run test case needs a .rei file selected or open"));
		new RunJob(testCase).schedule();
		return null;
	}

	/** The `rei` launcher: the preference, else `rei` on the PATH. */
	static String launcher() {
		String configured = InstanceScope.INSTANCE.getNode(ReiIds.PLUGIN).get(ReiIds.PREF_LAUNCHER, "").strip();
		return configured.isEmpty() ? "rei" : configured;
	}

	private static final class RunJob extends Job {
		private final IFile testCase;

		RunJob(IFile testCase) {
			super("Run test case " + testCase.getName());
			this.testCase = testCase;
			setUser(true);
		}

		@Override
		protected IStatus run(IProgressMonitor monitor) {
			Path file = testCase.getLocation().toFile().toPath();
			Path output = file.toAbsolutePath().getParent()
					.resolve(file.getFileName().toString().replaceFirst("\\.rei$", "") + "-run");
			List<String> command = List.of(launcher(), "run", file.toString(), "-o", output.toString());
			ReiConsole.println(String.join(" ", command));
			monitor.beginTask("rei run " + testCase.getName(), IProgressMonitor.UNKNOWN);
			try {
				ProcessResult result = ProcessResult.run(command, Generator.directoryOf(file), TIMEOUT_SECONDS,
						line -> {
							ReiConsole.println(line);
							monitor.subTask(line);
						}, monitor::isCanceled);
				GenerateJob.refresh(output);
				if (result.exitCode() == ProcessResult.STOPPED) {
					return monitor.isCanceled() ? Status.CANCEL_STATUS
							: Status.error("rei run " + testCase.getName() + " did not end in " + TIMEOUT_SECONDS + " s");
				}
				Path report = output.resolve("report.html");
				if (Files.isRegularFile(report)
						&& InstanceScope.INSTANCE.getNode(ReiIds.PLUGIN).getBoolean(ReiIds.PREF_OPEN_REPORT, true)) {
					Display.getDefault().asyncExec(() -> open(report));
				}
				// rei run's exit codes: 0 every requirement passed, 1 one failed, 2 and more the run itself failed
				return result.exitCode() <= 1 ? Status.info("rei run " + testCase.getName() + ": exit "
						+ result.exitCode() + ", report in " + report)
						: Status.error("rei run " + testCase.getName() + " failed (exit " + result.exitCode()
								+ "); its output is in the REI console");
			} catch (IOException notFound) {
				return Status.error("Cannot start the REI launcher '" + launcher() + "' (" + notFound.getMessage()
						+ "). Set Window > Preferences > REI > REI launcher to the rei script of your REI installation.");
			} catch (InterruptedException interrupted) {
				Thread.currentThread().interrupt();
				return Status.CANCEL_STATUS;
			} finally {
				monitor.done();
			}
		}

		private static void open(Path report) {
			try {
				PlatformUI.getWorkbench().getBrowserSupport().createBrowser("org.rei.eclipse.report")
						.openURL(report.toUri().toURL());
			} catch (PartInitException | MalformedURLException failed) {
				ReiPlugin.log("cannot open the report " + report, failed);
			}
		}

		@Override
		public boolean belongsTo(Object family) {
			return ReiIds.JOB_FAMILY.equals(family);
		}
	}
}
