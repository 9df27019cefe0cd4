/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.RobotType;
import org.rei.context.TestCase;
import org.rei.context.layout.LayoutProblem;
import org.rei.dsl.ReiStandaloneSetup;
import org.rei.generator.ArtifactGenerator;
import org.rei.generator.GenerationException;
import org.rei.generator.GeneratorOptions;
import org.rei.generator.RobotDescription;

import com.google.inject.Injector;

/**
 * Validates a .rei file and generates its artifacts, outside any IDE. Used by the command line and by the Maven
 * plugin; one instance can process many files (the language is set up once). Not final only so that the command
 * line's tests can make one file's check fail.
 */
public class HeadlessGenerator {

	/** What came of one file: its diagnostics and, when it generated, the files written. */
	public record Result(List<Diagnostic> diagnostics, List<Path> written) {
		public boolean hasErrors() {
			return diagnostics.stream().anyMatch(Diagnostic::isError);
		}
	}

	private final Injector injector;
	private final ArtifactGenerator generator;

	public HeadlessGenerator(Path templateOverrides) {
		this.injector = ReiStandaloneSetup.doSetup();
		this.generator = new ArtifactGenerator(new GeneratorOptions(templateOverrides));
	}

	/** Parses and validates; the file must exist (callers report missing files themselves). */
	public Result validate(Path file) {
		return new Result(diagnostics(file, load(file)), List.of());
	}

	/** Validates, then writes the artifacts into {@code outputDir} when there is no error. */
	public Result generate(Path file, Path outputDir) throws IOException {
		XtextResource resource = load(file);
		List<Diagnostic> diagnostics = diagnostics(file, resource);
		if (diagnostics.stream().anyMatch(Diagnostic::isError)) {
			return new Result(diagnostics, List.of());
		}
		if (!(resource.getContents().get(0) instanceof TestCase testCase)) {
			return new Result(List.of(new Diagnostic(file, 1, 1, Diagnostic.Severity.ERROR, "This file is a catalogue: "
					+ "nothing to generate; a test case uses its types with 'import \"" + file.getFileName() + "\"'",
					null)), List.of());
		}
		Files.createDirectories(outputDir);
		try {
			List<Path> written = generator.generate(testCase, outputDir);
			return new Result(withDescriptionWarnings(file, testCase, diagnostics), written);
		} catch (GenerationException e) {
			List<Diagnostic> all = new ArrayList<>(diagnostics);
			if (e.problems().isEmpty()) {
				all.add(new Diagnostic(file, 1, 1, Diagnostic.Severity.ERROR, e.getMessage(), null));
			}
			for (LayoutProblem problem : e.problems()) {
				all.add(at(file, problem.element(), problem.feature(), problem.message(), problem.code()));
			}
			return new Result(all, List.of());
		}
	}

	/**
	 * Validates a catalogue file and describes its types as JSON for tools that furnish rooms with them
	 * ({@code rei gen-rooms --catalogue}): name, category, shape, size [x, y, height], mass, colour. A robot read from
	 * its description: the rectangle centred on its origin that holds its footprint, and its lidar's height (a
	 * description that does not read is an error at its entry).
	 */
	public CatalogueResult describeCatalogue(Path file) {
		XtextResource resource = load(file);
		List<Diagnostic> diagnostics = diagnostics(file, resource);
		if (diagnostics.stream().anyMatch(Diagnostic::isError)) {
			return new CatalogueResult(diagnostics, null);
		}
		if (!(resource.getContents().get(0) instanceof Catalogue catalogue)) {
			return new CatalogueResult(List.of(new Diagnostic(file, 1, 1, Diagnostic.Severity.ERROR,
					"Expected a catalogue ('catalogue NAME { ... }'), this is a test case", null)), null);
		}
		StringBuilder json = new StringBuilder("{\"name\": ").append(quote(catalogue.getName())).append(", \"types\": [");
		String separator = "";
		for (ObjectType type : catalogue.getOwnedTypes()) {
			double[] size = { type.getSizeX(), type.getSizeY() };
			double height = type.getSizeZ();
			if (org.rei.catalogue.util.Polygons.isPolygon(type)) { // a polygon by its bounding box, which holds it
				double[] b = org.rei.catalogue.util.Polygons.bounds(org.rei.catalogue.util.Polygons.points(type));
				size = new double[] { b[2] - b[0], b[3] - b[1] };
			}
			if (type instanceof RobotType robot && robot.getDescription() != null) {
				// a described robot has no box (its sizes were the metamodel's 1 x 1 m): the rectangle centred on
				// its origin that holds its footprint, as the rooms' check takes a robot, and its lidar's height
				try {
					RobotDescription d = RobotDescription.read(robot);
					size = new double[] { 2 * Math.max(-d.xmin(), d.xmax()), 2 * Math.max(-d.ymin(), d.ymax()) };
					height = d.lidarZ();
				} catch (GenerationException e) {
					List<Diagnostic> all = new ArrayList<>(diagnostics);
					for (LayoutProblem problem : e.problems()) {
						all.add(at(file, problem.element(), problem.feature(), problem.message(), problem.code()));
					}
					return new CatalogueResult(all, null);
				}
			}
			json.append(separator).append("\n  {\"name\": ").append(quote(type.getName()))
					.append(", \"category\": ").append(quote(type.getCategory().getName()))
					.append(", \"shape\": ").append(quote(type.getShape().getName()))
					.append(", \"size\": [").append(size[0]).append(", ").append(size[1]).append(", ")
					.append(height).append("], \"mass\": ").append(type.getMass())
					.append(", \"colour\": ").append(quote(type.getColour())).append('}');
			separator = ",";
		}
		return new CatalogueResult(diagnostics, json.append("\n]}").toString());
	}

	/** Diagnostics of a catalogue file and, when it is valid, its types as JSON. */
	public record CatalogueResult(List<Diagnostic> diagnostics, String json) {
	}

	private static String quote(String text) {
		if (text == null) {
			return "null";
		}
		StringBuilder out = new StringBuilder("\"");
		for (char c : text.toCharArray()) {
			if (c == '"' || c == '\\') {
				out.append('\\').append(c);
			} else if (c < 0x20) {
				out.append(String.format("\\u%04x", (int) c));
			} else {
				out.append(c);
			}
		}
		return out.append('"').toString();
	}

	private XtextResource load(Path file) {
		XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
		return (XtextResource) resourceSet.getResource(URI.createFileURI(file.toAbsolutePath().toString()), true);
	}

	/** The file's problems, then those of the catalogues it imports, each with its own file and position. */
	private List<Diagnostic> diagnostics(Path file, XtextResource resource) {
		List<Diagnostic> result = issues(file, resource);
		if (result.isEmpty() && resource.getContents().isEmpty()) {
			result.add(new Diagnostic(file, 1, 1, Diagnostic.Severity.ERROR,
					"Expected a test case ('testcase NAME { ... }') or a catalogue ('catalogue NAME { ... }')", null));
		}
		for (Resource other : List.copyOf(resource.getResourceSet().getResources())) {
			if (other != resource && other instanceof XtextResource imported && other.getURI().isFile()
					&& !imported.getContents().isEmpty() && imported.getContents().get(0) instanceof Catalogue) {
				result.addAll(issues(asGiven(Path.of(other.getURI().toFileString())), imported));
			}
		}
		return result;
	}

	/** A path under the working directory as a relative one, as a user would have typed it. */
	private static Path asGiven(Path absolute) {
		Path here = Path.of("").toAbsolutePath();
		return absolute.startsWith(here) ? here.relativize(absolute) : absolute;
	}

	private static List<Diagnostic> issues(Path file, XtextResource resource) {
		IResourceValidator validator = resource.getResourceServiceProvider().getResourceValidator();
		List<Diagnostic> result = new ArrayList<>();
		for (Issue issue : validator.validate(resource, CheckMode.ALL, CancelIndicator.NullImpl)) {
			Diagnostic.Severity severity = switch (issue.getSeverity()) {
			case ERROR -> Diagnostic.Severity.ERROR;
			case WARNING -> Diagnostic.Severity.WARNING;
			default -> null;
			};
			if (severity != null) {
				result.add(new Diagnostic(file, orOne(issue.getLineNumber()), orOne(issue.getColumn()), severity,
						issue.getMessage(), issue.getCode()));
			}
		}
		return result;
	}

	/**
	 * {@code diagnostics} and what the robot's description read but did not use (a visual mesh that is not there:
	 * the simulator's body is the collision shapes), as warnings at its catalogue entry.
	 */
	private static List<Diagnostic> withDescriptionWarnings(Path file, TestCase testCase, List<Diagnostic> diagnostics)
			throws GenerationException {
		var robot = testCase.getOwnedEnvironment() == null ? null : testCase.getOwnedEnvironment().getOwnedRobot();
		if (robot == null || !(robot.getType() instanceof RobotType type) || type.getDescription() == null) {
			return diagnostics;
		}
		List<Diagnostic> all = new ArrayList<>(diagnostics);
		for (String warning : RobotDescription.read(type).warnings()) { // read already: this generation's
			Diagnostic error = at(file, type, null, "The robot's description: " + warning,
					RobotDescription.PROBLEM_CODE);
			all.add(new Diagnostic(error.file(), error.line(), error.column(), Diagnostic.Severity.WARNING,
					error.message(), error.code()));
		}
		return all;
	}

	private static Diagnostic at(Path file, EObject element, EStructuralFeature feature, String message, String code) {
		List<INode> nodes = feature == null ? List.of() : NodeModelUtils.findNodesForFeature(element, feature);
		INode node = nodes.isEmpty() ? NodeModelUtils.findActualNodeFor(element) : nodes.get(0);
		for (EObject e = element; node == null && e != null; e = e.eContainer()) {
			node = NodeModelUtils.findActualNodeFor(e);
		}
		int line = node == null ? 1 : node.getStartLine();
		int column = 1;
		if (node != null) {
			String text = node.getRootNode().getText();
			column = node.getOffset() - text.lastIndexOf('\n', node.getOffset() - 1);
		}
		// a problem of an imported catalogue's entry (a robot's description) is that file's, at its line
		org.eclipse.emf.common.util.URI uri = element.eResource() == null ? null : element.eResource().getURI();
		Path where = uri != null && uri.isFile() ? Path.of(uri.toFileString()) : file;
		return new Diagnostic(where, line, column, Diagnostic.Severity.ERROR, message, code);
	}

	private static int orOne(Integer value) {
		return value == null || value < 1 ? 1 : value;
	}
}
