// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.commands;

import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.core.runtime.preferences.InstanceScope;
import org.rei.eclipse.ReiIds;
import org.rei.eclipse.lsp.Jars;

/**
 * Generate artifacts: the shipped generator jar, exactly as {@code rei generate FILE -o OUT} runs it, so the
 * editor writes the same five files as the command line.
 */
public final class Generator {
	/** Where the artifacts go unless the preference says otherwise: beside the file, in a folder of its name. */
	public static final String DEFAULT_OUTPUT = "${name}-artifacts";
	private static final long TIMEOUT_SECONDS = 120;

	private Generator() {
	}

	/** The output folder for a test case: the preference, relative to the file's folder unless absolute. */
	public static Path outputFor(Path testCase) {
		String pattern = InstanceScope.INSTANCE.getNode(ReiIds.PLUGIN).get(ReiIds.PREF_OUTPUT_FOLDER, DEFAULT_OUTPUT)
				.strip();
		String name = testCase.getFileName().toString().replaceFirst("\\.rei$", "");
		Path folder = Path.of((pattern.isEmpty() ? DEFAULT_OUTPUT : pattern).replace("${name}", name));
		return folder.isAbsolute() ? folder : testCase.toAbsolutePath().getParent().resolve(folder).normalize();
	}

	/** Runs the generator; the result has its exit code (0 written, 1 invalid test case, 2 usage) and output. */
	public static ProcessResult generate(Path testCase, Path output) throws IOException, InterruptedException {
		Path jar = Jars.locate(Jars.GENERATOR);
		List<String> command = List.of(Jars.java(), "-jar", jar.toString(), "generate", testCase.toString(), "-o",
				output.toString());
		return ProcessResult.run(command, testCase.getParent().toFile(), TIMEOUT_SECONDS, null);
	}

	static File directoryOf(Path file) {
		return file.toAbsolutePath().getParent().toFile();
	}
}
