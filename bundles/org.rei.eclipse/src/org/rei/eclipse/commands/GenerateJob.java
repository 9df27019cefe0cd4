// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.commands;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;
import org.rei.eclipse.ReiIds;

/** Generate artifacts of one test case in the background, then show the new files in the workspace. */
public final class GenerateJob extends Job {
	private static final Map<Path, Object> RUNNING = new ConcurrentHashMap<>();
	private final IFile testCase;

	public GenerateJob(IFile testCase) {
		super("Generate artifacts of " + testCase.getName());
		this.testCase = testCase;
		setUser(false);
	}

	@Override
	protected IStatus run(IProgressMonitor monitor) {
		Path file = testCase.getLocation().toFile().toPath();
		Path output = Generator.outputFor(file);
		// Two generations of one file run one after the other. Not a scheduling rule: the refresh below needs
		// the rule of the output's nearest existing folder, which a rule on the file would not contain.
		synchronized (RUNNING.computeIfAbsent(file, key -> new Object())) {
			return generate(file, output);
		}
	}

	private IStatus generate(Path file, Path output) {
		try {
			ProcessResult result = Generator.generate(file, output);
			ReiConsole.println("rei generate " + testCase.getFullPath() + " -o " + output);
			ReiConsole.println(result.output().stripTrailing());
			refresh(output);
			return switch (result.exitCode()) {
			case 0 -> Status.info("Generated the artifacts of " + testCase.getName() + " in " + output);
			case 1 -> Status.warning(testCase.getName() + " is not valid: nothing generated (see the Problems view"
					+ " and the REI console)");
			default -> Status.error("Generate artifacts of " + testCase.getName() + " failed (exit "
					+ result.exitCode() + "):\n" + result.output());
			};
		} catch (IOException failed) {
			return Status.error("Generate artifacts of " + testCase.getName() + ": " + failed.getMessage(), failed);
		} catch (InterruptedException interrupted) {
			Thread.currentThread().interrupt();
			return Status.CANCEL_STATUS;
		}
	}

	/** The output folder as the workspace sees it, when it is inside the workspace: from its nearest existing
	 * ancestor, since a folder the generator just created is not yet a resource. */
	static void refresh(Path folder) {
		for (IContainer container : ResourcesPlugin.getWorkspace().getRoot()
				.findContainersForLocationURI(folder.toUri())) {
			IContainer existing = container;
			while (!existing.exists() && existing.getParent() != null) {
				existing = existing.getParent();
			}
			try {
				existing.refreshLocal(IResource.DEPTH_INFINITE, null);
			} catch (CoreException ignored) {
				// the files are written; the workspace shows them at its next refresh
			}
		}
	}

	@Override
	public boolean belongsTo(Object family) {
		return ReiIds.JOB_FAMILY.equals(family);
	}
}
