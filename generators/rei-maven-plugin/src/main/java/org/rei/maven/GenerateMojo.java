/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maven;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.rei.cli.Diagnostic;
import org.rei.cli.HeadlessGenerator;

/**
 * Validates every {@code .rei} test case under {@code src/test/rei} and generates its artifacts into
 * {@code target/rei/<path of the case without .rei>/}. Any error in any case fails the build after all cases were
 * checked, so one build reports every broken file.
 */
@Mojo(name = "generate", defaultPhase = LifecyclePhase.GENERATE_TEST_RESOURCES, threadSafe = true)
public class GenerateMojo extends AbstractMojo {

	@Parameter(property = "rei.sourceDirectory", defaultValue = "${project.basedir}/src/test/rei")
	private File sourceDirectory;

	@Parameter(property = "rei.outputDirectory", defaultValue = "${project.build.directory}/rei")
	private File outputDirectory;

	/** A folder of EGL templates that replace the built-in ones of the same name. */
	@Parameter(property = "rei.templates")
	private File templates;

	@Parameter(property = "rei.skip", defaultValue = "false")
	private boolean skip;

	@Override
	public void execute() throws MojoExecutionException, MojoFailureException {
		if (skip) {
			getLog().info("REI generation skipped");
			return;
		}
		Path sources = sourceDirectory.toPath();
		if (!Files.isDirectory(sources)) {
			getLog().info("No REI test cases: " + sources + " does not exist");
			return;
		}
		List<Path> cases = testCases(sources);
		HeadlessGenerator generator = new HeadlessGenerator(templates == null ? null : templates.toPath());
		int failed = 0;
		for (Path file : cases) {
			String relative = sources.relativize(file).toString();
			Path out = outputDirectory.toPath().resolve(relative.substring(0, relative.length() - ".rei".length()));
			HeadlessGenerator.Result result;
			try {
				result = generator.generate(file, out);
			} catch (IOException e) {
				throw new MojoExecutionException("Cannot write the artifacts of " + file + " to " + out, e);
			}
			for (Diagnostic diagnostic : result.diagnostics()) {
				if (diagnostic.isError()) {
					getLog().error(diagnostic.toString());
				} else {
					getLog().warn(diagnostic.toString());
				}
			}
			if (result.hasErrors()) {
				failed++;
			} else {
				getLog().info("Generated " + relative + " -> " + out);
			}
		}
		if (failed > 0) {
			throw new MojoFailureException(failed + " of " + cases.size() + " REI test case(s) have errors (listed above)");
		}
		getLog().info("Generated " + cases.size() + " REI test case(s)");
	}

	private static List<Path> testCases(Path sources) throws MojoExecutionException {
		try (Stream<Path> files = Files.walk(sources)) {
			return files.filter(p -> p.toString().endsWith(".rei") && Files.isRegularFile(p)).sorted().toList();
		} catch (IOException e) {
			throw new MojoExecutionException("Cannot list " + sources, e);
		}
	}
}
