/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.epsilon.egl.EglModule;
import org.eclipse.epsilon.egl.execute.context.EglContext;
import org.eclipse.epsilon.emc.emf.InMemoryEmfModel;
import org.eclipse.epsilon.eol.exceptions.EolRuntimeException;
import org.eclipse.epsilon.eol.execute.context.FrameStack;
import org.eclipse.epsilon.eol.execute.context.Variable;
import org.eclipse.epsilon.eol.models.ModelRepository;
import org.rei.catalogue.RobotType;
import org.rei.catalogue.util.Catalogues;
import org.rei.context.ContextFactory;
import org.rei.context.TestCase;
import org.rei.context.layout.FloorLayout;
import org.rei.mission.MissionPackage;
import org.rei.runtime.RuntimePackage;

/**
 * Turns an abstract test case into the five artifacts of docs/artifacts.md: lays out the floors, maps the test case
 * to the concrete environment and mission models, and runs one EGL template per artifact over them.
 * <p>
 * Templates are parsed once, in the constructor, and reused by every {@link #generate} call. An instance is not
 * meant for concurrent use: {@link #generate} is synchronized because the parsed templates keep run state.
 */
public final class ArtifactGenerator {

	/** The artifacts in the order they are written; each has a template named {@code <artifact>.egl}. */
	public static final List<String> ARTIFACTS = List.of("world.sdf", "world.json", "mission.xml", "animation.json",
			"monitor.json");

	/** The expanded URDF of a robot read from a description, in the case folder (world.json's robot.description). */
	public static final String ROBOT_URDF = "robot.urdf";

	/**
	 * The files the description was read from (itself, what xacro included, the collision meshes), an absolute path
	 * a line: what a campaign's resume checks besides the case and its catalogues before it keeps a generated case.
	 */
	public static final String ROBOT_SOURCES = "robot.sources";

	private static final String TEMPLATE_FOLDER = "/org/rei/generator/templates/";

	private final Map<String, EglModule> templates = new LinkedHashMap<>();
	private final ConcreteMapping mapping;

	/**
	 * Parses the templates.
	 *
	 * @throws IllegalArgumentException when a template (built-in or override) does not parse
	 */
	public ArtifactGenerator(GeneratorOptions options) {
		this.mapping = new ConcreteMapping(Catalogues.loadDefault(new ResourceSetImpl()));
		Path overrides = options == null ? null : options.templateOverrides();
		for (String artifact : ARTIFACTS) {
			String name = artifact + ".egl";
			Path override = overrides == null ? null : overrides.resolve(name);
			templates.put(artifact, override != null && Files.isRegularFile(override) ? parse(override) : parse(name));
		}
	}

	/**
	 * Writes the artifacts of one test case into {@code outputDir} (created when missing), overwriting what is
	 * there.
	 *
	 * @param testCase a test case with resolved cross-references; types may be missing on floors, walls, humans and
	 *                 the robot (the default catalogue's Floor, Wall, Human and Waffle are used)
	 * @return the written files in {@link #ARTIFACTS} order, then for a room from an occupancy map the copies of its
	 *         YAML and image
	 * @throws GenerationException when the room cannot be laid out ({@link GenerationException#problems()}), an
	 *                             object is not on a floor, a template fails or a file cannot be written
	 */
	public synchronized List<Path> generate(TestCase testCase, Path outputDir) throws GenerationException {
		if (testCase.getOwnedEnvironment() == null) {
			throw new GenerationException("test case " + testCase.getName() + " has no environment");
		}
		MapRoom mapRoom = MapRoom.of(testCase.getOwnedEnvironment());
		FloorLayout layout = mapRoom == null
				? FloorLayout.compute(testCase.getOwnedEnvironment(), mapping.defaultWallType())
				: FloorLayout.compute(testCase.getOwnedEnvironment(), mapping.defaultWallType(),
						mapRoom.map().originX(), mapRoom.map().originY());
		if (!layout.isValid()) {
			throw new GenerationException("the room of " + testCase.getName() + " cannot be laid out: "
					+ layout.problems().get(0).message()
					+ (layout.problems().size() > 1 ? " (and " + (layout.problems().size() - 1) + " more)" : ""),
					layout.problems());
		}
		ConcreteMapping.Result model = mapping.map(testCase, layout, mapRoom);
		RobotDescription description = null;
		if (model.robot() != null && model.robot().getType() instanceof RobotType type
				&& type.getDescription() != null) {
			description = RobotDescription.read(type);
			// the box a description's robot fits in, for what still reads a size (its footprint is in world.json)
			model.robot().setSizeX(description.xmax() - description.xmin());
			model.robot().setSizeY(description.ymax() - description.ymin());
			model.robot().setSizeZ(description.lidarZ());
		}
		TemplateSupport support = new TemplateSupport(layout, model, outputDir, mapRoom, description);
		try {
			Files.createDirectories(outputDir);
		} catch (IOException e) {
			throw new GenerationException("cannot create " + outputDir, e);
		}
		InMemoryEmfModel world = new InMemoryEmfModel("World", model.environment().eResource(), RuntimePackage.eINSTANCE);
		InMemoryEmfModel mission = new InMemoryEmfModel("Mission", model.mission().eResource(), MissionPackage.eINSTANCE);
		List<Path> written = new ArrayList<>();
		for (Map.Entry<String, EglModule> entry : templates.entrySet()) {
			String text = run(entry.getKey(), entry.getValue(), List.of(world, mission), variables(testCase, model, support));
			Path file = outputDir.resolve(entry.getKey());
			try {
				Files.writeString(file, text, StandardCharsets.UTF_8);
			} catch (IOException e) {
				throw new GenerationException("cannot write " + file, e);
			}
			written.add(file);
		}
		if (mapRoom != null) {
			written.addAll(mapRoom.copyInto(outputDir));
		}
		if (description != null) { // the simulator's body: the expanded description, as the case folder's own file
			Path urdf = outputDir.resolve(ROBOT_URDF);
			Path sources = outputDir.resolve(ROBOT_SOURCES);
			try {
				Files.writeString(urdf, description.urdf(), StandardCharsets.UTF_8);
				Files.write(sources, description.sources().stream().map(p -> p.toAbsolutePath().toString()).toList(),
						StandardCharsets.UTF_8);
			} catch (IOException e) {
				throw new GenerationException("cannot write " + urdf + " or " + sources, e);
			}
			written.add(urdf);
			written.add(sources);
		}
		return written;
	}

	private static Variable[] variables(TestCase testCase, ConcreteMapping.Result model, TemplateSupport support) {
		var monitor = testCase.getOwnedMonitor() != null ? testCase.getOwnedMonitor()
				: ContextFactory.eINSTANCE.createMonitorSpec(); // carries the metamodel's defaults
		return new Variable[] { Variable.createReadOnlyVariable("gen", support),
				Variable.createReadOnlyVariable("testcase", testCase.getName()),
				Variable.createReadOnlyVariable("world", model.environment()),
				Variable.createReadOnlyVariable("mission", model.mission()),
				Variable.createReadOnlyVariable("bodies", model.bodies()),
				Variable.createReadOnlyVariable("floors", model.floors()),
				Variable.createReadOnlyVariable("robot", model.robot()),
				Variable.createReadOnlyVariable("animated", model.animated()),
				Variable.createReadOnlyVariable("people", model.people()),
				Variable.createReadOnlyVariable("types", model.types()),
				Variable.createReadOnlyVariable("monitor", monitor),
				Variable.createReadOnlyVariable("faults", Faults.of(testCase)) };
	}

	private static String run(String artifact, EglModule module, List<InMemoryEmfModel> models, Variable[] variables)
			throws GenerationException {
		ModelRepository repository = module.getContext().getModelRepository();
		FrameStack frames = module.getContext().getFrameStack();
		repository.addModels(models);
		frames.putGlobal(variables);
		try {
			return String.valueOf(module.execute());
		} catch (EolRuntimeException | RuntimeException e) {
			throw new GenerationException("template " + artifact + ".egl failed: " + e.getMessage(), e);
		} finally {
			// leave the parsed module clean for the next test case, and let go of this one's models
			for (InMemoryEmfModel model : models) {
				repository.removeModel(model);
			}
			for (Variable variable : variables) {
				frames.putGlobal(Variable.createReadOnlyVariable(variable.getName(), null));
			}
		}
	}

	private static EglModule parse(String builtIn) {
		try (InputStream in = ArtifactGenerator.class.getResourceAsStream(TEMPLATE_FOLDER + builtIn)) {
			if (in == null) {
				throw new IllegalStateException("built-in template missing: " + builtIn);
			}
			EglModule module = new EglModule();
			module.parse(new String(in.readAllBytes(), StandardCharsets.UTF_8));
			return checked(module, builtIn);
		} catch (IllegalStateException e) {
			throw e;
		} catch (Exception e) {
			throw new IllegalStateException("cannot parse built-in template " + builtIn, e);
		}
	}

	private static EglModule parse(Path override) {
		try {
			EglModule module = new EglModule();
			module.parse(override.toFile());
			return checked(module, override.toString());
		} catch (IllegalArgumentException e) {
			throw e;
		} catch (Exception e) {
			throw new IllegalArgumentException("cannot parse template " + override, e);
		}
	}

	private static EglModule checked(EglModule module, String name) {
		if (!module.getParseProblems().isEmpty()) {
			throw new IllegalArgumentException("template " + name + " does not parse: " + module.getParseProblems());
		}
		EglContext context = (EglContext) module.getContext();
		context.setOperationContributorRegistry(new HelperCallRegistry(context.getOperationContributorRegistry()));
		return module;
	}
}
