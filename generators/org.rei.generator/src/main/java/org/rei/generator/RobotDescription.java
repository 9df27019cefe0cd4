/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

import org.rei.catalogue.CataloguePackage;
import org.rei.catalogue.RobotType;
import org.rei.catalogue.util.RobotDescriptions;
import org.rei.context.layout.LayoutProblem;

/**
 * What a robot type's URDF or xacro description gives world.json: the footprint (JSON written as it is), its
 * bounding box, the lidar's pose and the differential drive when the wheel joints say it (docs/robots.md).
 * <p>
 * The description is read by REI's Python reader ({@code rei robot FILE --for-generator URDF_OUT}: xacro and
 * ROS's URDF parser exist in Python only), run as {@code $REI_PYTHON -m rei.cli} ({@code python3} when unset; the
 * {@code rei} command sets it to its own interpreter). Its error, one line naming the file and its line, becomes
 * a problem positioned at the catalogue entry. Reads are kept per file and arguments, so a campaign's JVM reads a
 * description once, and read again when a file the read depends on changed (the reader's {@code source} lines: the
 * description, the files xacro included, the collision meshes): a warm JVM kept a footprint from an edited include.
 */
public record RobotDescription(String footprintJson, double xmin, double ymin, double xmax, double ymax,
		double lidarX, double lidarY, double lidarZ, double lidarYaw, Double wheelSeparation, Double wheelRadius,
		String urdf, List<Path> sources, List<String> warnings) {

	/** The code of the problem a description that does not read gives. */
	public static final String PROBLEM_CODE = "org.rei.dsl.robotDescription";

	private static final long TIMEOUT_SECONDS = 120;
	private static final String WARNING = "rei: warning: ";
	private static final Map<List<Object>, Read> READ = new ConcurrentHashMap<>();

	/** A description as read, with the size and modification time of each file it was read from. */
	private record Read(RobotDescription description, Map<Path, List<Long>> stamps) {
		boolean fresh() {
			return stamps.entrySet().stream().allMatch(e -> e.getValue().equals(stamp(e.getKey())));
		}
	}

	/** Size and modification time; a file that is gone: [-1, -1]. */
	private static List<Long> stamp(Path file) {
		try {
			return List.of(Files.size(file), Files.getLastModifiedTime(file).toMillis());
		} catch (IOException e) {
			return List.of(-1L, -1L);
		}
	}

	/** The robot type's description, or a problem at its catalogue entry when it does not read. */
	public static RobotDescription read(RobotType type) throws GenerationException {
		Path file = RobotDescriptions.file(type);
		if (file == null || !Files.isRegularFile(file)) {
			throw problem(type, "Cannot read the robot's description '" + type.getDescription() + "': no such file");
		}
		String lidar = type.getLidar() == null ? null : type.getLidar().getLink();
		List<String> args = new ArrayList<>();
		for (int i = 0; i < type.getDescriptionArgNames().size(); i++) {
			args.add("--arg");
			args.add(type.getDescriptionArgNames().get(i) + ":=" + type.getDescriptionArgValues().get(i));
		}
		// the simulator's wheels when the description's are not read: the reader checks they lie in the footprint
		args.addAll(List.of("--wheels", Double.toString(type.getWheelRadius()),
				Double.toString(type.getWheelSeparation())));
		List<Object> key = List.of(file.toAbsolutePath().normalize(), args, String.valueOf(lidar));
		Read known = READ.get(key);
		if (known == null || !known.fresh()) {
			known = run(type, file, args, lidar);
			READ.put(key, known);
		}
		return known.description();
	}

	private static Read run(RobotType type, Path file, List<String> args, String lidar)
			throws GenerationException {
		String python = System.getenv().getOrDefault("REI_PYTHON", "python3");
		List<Long> before = stamp(file);
		Path urdfOut;
		Path output;
		try {
			urdfOut = Files.createTempFile("rei-robot-", ".urdf");
			output = Files.createTempFile("rei-robot-", ".txt");
		} catch (IOException e) {
			throw new GenerationException("cannot create a temporary file for the robot's description", e);
		}
		List<String> command = new ArrayList<>(List.of(python, "-m", "rei.cli", "robot", file.toString()));
		command.addAll(args);
		if (lidar != null) {
			command.addAll(List.of("--lidar", lidar));
		}
		command.addAll(List.of("--for-generator", urdfOut.toString()));
		try {
			Process process = new ProcessBuilder(command).redirectErrorStream(true)
					.redirectOutput(output.toFile()).start();
			process.getOutputStream().close(); // the reader reads no input
			if (!process.waitFor(TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
				process.destroyForcibly();
				throw problem(type, "Reading the robot's description took more than " + TIMEOUT_SECONDS + " s");
			}
			List<String> lines = Files.readAllLines(output, StandardCharsets.UTF_8);
			if (process.exitValue() != 0) {
				String error = lines.stream().filter(l -> l.startsWith("rei: error: ")).findFirst()
						.map(l -> l.substring("rei: error: ".length())).orElse(String.join(" ", lines).strip());
				throw problem(type, "The robot's description does not read: " + error);
			}
			// the description stamped before the read; its sources are known only after it
			Map<Path, List<Long>> stamps = new LinkedHashMap<>();
			stamps.put(file, before);
			lines.stream().filter(l -> l.startsWith("source ")).map(l -> Path.of(l.substring("source ".length())))
					.forEach(source -> stamps.putIfAbsent(source, stamp(source)));
			return new Read(parse(type, lines, Files.readString(urdfOut, StandardCharsets.UTF_8),
					List.copyOf(stamps.keySet())), stamps);
		} catch (IOException e) {
			throw problem(type, "Cannot run REI's description reader (" + python + " -m rei.cli robot; set REI_PYTHON "
					+ "to the Python that has REI installed): " + e.getMessage());
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new GenerationException("interrupted while reading the robot's description", e);
		} finally {
			try {
				Files.deleteIfExists(urdfOut);
				Files.deleteIfExists(output);
			} catch (IOException e) {
				// a temporary file left behind is not worth failing the generation for
			}
		}
	}

	private static RobotDescription parse(RobotType type, List<String> lines, String urdf, List<Path> sources)
			throws GenerationException {
		String footprint = null;
		double[] bounds = null;
		double[] lidar = null;
		double[] drive = null;
		boolean noDrive = false;
		for (String line : lines) {
			if (line.startsWith("footprint ")) {
				footprint = line.substring("footprint ".length());
			} else if (line.startsWith("bounds ")) {
				bounds = numbers(line, 4);
			} else if (line.startsWith("lidar ")) {
				lidar = numbers(line, 4);
			} else if (line.equals("drive none")) {
				noDrive = true;
			} else if (line.startsWith("drive ")) {
				drive = numbers(line, 2);
			}
		}
		if (footprint == null || bounds == null || lidar == null || (drive == null && !noDrive)) {
			throw problem(type, "The description reader's answer lacks a line: " + lines);
		}
		// what the reader read but did not use (visual meshes that are not there): the generation's warnings
		List<String> warnings = lines.stream().filter(l -> l.startsWith(WARNING))
				.map(l -> l.substring(WARNING.length())).toList();
		return new RobotDescription(footprint, bounds[0], bounds[1], bounds[2], bounds[3], lidar[0], lidar[1],
				lidar[2], lidar[3], drive == null ? null : drive[0], drive == null ? null : drive[1], urdf, sources,
				warnings);
	}

	private static double[] numbers(String line, int count) {
		String[] words = line.split(" ");
		double[] values = new double[count];
		for (int i = 0; i < count; i++) {
			values[i] = Double.parseDouble(words[i + 1]);
		}
		return values;
	}

	private static GenerationException problem(RobotType type, String message) {
		return new GenerationException(message, List.of(new LayoutProblem(type,
				CataloguePackage.Literals.ROBOT_TYPE__DESCRIPTION, PROBLEM_CODE, message)));
	}
}
