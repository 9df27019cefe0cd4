/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.rei.catalogue.Catalogue;
import org.rei.catalogue.CataloguePackage;
import org.rei.catalogue.Lidar;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.RobotType;
import org.rei.catalogue.Shape;
import org.rei.catalogue.util.Catalogues;
import org.rei.catalogue.util.Polygons;
import org.rei.catalogue.util.RobotDescriptions;
import org.rei.context.ContextPackage;
import org.rei.context.TestCase;
import org.rei.dsl.catalogue.CatalogueImports;

/**
 * User catalogues (thesis 4.1.3): a test case's imports must name readable, valid catalogues whose type names
 * clash with no other; a declared type must be something the simulator can build.
 */
public class CatalogueValidator extends ReiCheckBase {

	/** Lowest robot the generated URDF fits a chassis into (above its ground clearance), in metres. */
	static final double MIN_ROBOT_HEIGHT = 0.05;
	static final int MAX_BEAMS = 4096;
	static final double MAX_LIDAR_RATE = 100;

	private static final Pattern COLOUR = Pattern.compile("#(\\p{XDigit}{6}|\\p{XDigit}{8})");
	private static final CataloguePackage CAT = CataloguePackage.eINSTANCE;

	@Override
	protected List<EPackage> getEPackages() {
		return List.of(ContextPackage.eINSTANCE, CataloguePackage.eINSTANCE);
	}

	@Check
	public void checkImports(TestCase testCase) {
		Map<String, String> typeSource = new HashMap<>();
		for (CatalogueImports.Import i : CatalogueImports.of(testCase)) {
			if (i.problem() != null) {
				importError(testCase, i, i.problem(), ReiIssueCodes.CATALOGUE_IMPORT);
				continue;
			}
			if (!i.resource().getErrors().isEmpty()) {
				// its other errors are reported on the catalogue itself (rei validate lists both files)
				Resource.Diagnostic first = i.resource().getErrors().get(0);
				importError(testCase, i, "The catalogue '" + i.path() + "' does not parse: line " + first.getLine()
						+ ", column " + first.getColumn() + ": " + first.getMessage(), ReiIssueCodes.CATALOGUE_INVALID);
				continue;
			}
			Map<String, List<String>> clashes = new TreeMap<>(); // earlier file -> type names, reported once
			for (ObjectType type : i.catalogue().getOwnedTypes()) {
				String earlier = typeSource.putIfAbsent(type.getName(), i.path());
				if (earlier != null && !earlier.equals(i.path())) { // a file's own duplicates are its errors
					clashes.computeIfAbsent(earlier, k -> new ArrayList<>()).add(type.getName());
				}
			}
			clashes.forEach((earlier, names) -> importError(testCase, i, (names.size() == 1 ? "Type " : "Types ")
					+ String.join(", ", names) + " of '" + i.path() + "' " + (names.size() == 1 ? "is" : "are")
					+ " also declared in '" + earlier + "': a type name must mean one type",
					ReiIssueCodes.DUPLICATE_NAME));
		}
	}

	@Check
	public void checkNames(Catalogue catalogue) {
		Map<String, ObjectType> seen = new HashMap<>();
		Catalogue defaults = Catalogues.loadDefault(catalogue.eResource().getResourceSet());
		for (ObjectType type : catalogue.getOwnedTypes()) {
			if (type.getName() == null) {
				continue;
			}
			ObjectType first = seen.putIfAbsent(type.getName(), type);
			if (first != null) {
				error("Duplicate type name '" + type.getName() + "': already declared on line "
						+ NodeModelUtils.getNode(first).getStartLine(), type, CAT.getObjectType_Name(),
						ReiIssueCodes.DUPLICATE_NAME);
			} else if (Catalogues.find(defaults, type.getName()).isPresent()) {
				error("Type " + type.getName() + " is in the default catalogue already: choose another name",
						type, CAT.getObjectType_Name(), ReiIssueCodes.DUPLICATE_NAME);
			}
		}
	}

	@Check
	public void checkType(ObjectType type) {
		if (!(type.eContainer() instanceof Catalogue)) {
			return;
		}
		if (!(type instanceof RobotType robot && robot.getDescription() != null)) { // a description gives the sizes
			positive(type, CAT.getObjectType_SizeX(), "x size");
			positive(type, CAT.getObjectType_SizeY(), "y size");
			positive(type, CAT.getObjectType_SizeZ(), "height");
		}
		if (type.getShape() == Shape.CYLINDER && type.getSizeX() > 0 && type.getSizeY() != type.getSizeX()) {
			error("A cylinder stands on a circle: its x and y sizes are the diameter, expected " + type.getSizeX()
					+ " twice", type, CAT.getObjectType_SizeY(), ReiIssueCodes.CYLINDER_SIZE);
		}
		boolean moves = type.getCategory() == ObjectCategory.HUMAN || type.getCategory() == ObjectCategory.DYNAMIC
				|| type instanceof RobotType;
		if (moves && !(type.getMass() > 0)) {
			error("A " + (type instanceof RobotType ? "robot" : type.getCategory().getLiteral().toLowerCase())
					+ " moves in the simulator: its mass must be above 0 kg", type, CAT.getObjectType_Mass(),
					ReiIssueCodes.NON_POSITIVE);
		} else if (type.getMass() < 0) {
			error("The mass must not be negative (0 kg: fixed in the world)", type, CAT.getObjectType_Mass(),
					ReiIssueCodes.NON_POSITIVE);
		}
		if (type.getColour() != null && !COLOUR.matcher(type.getColour()).matches()) {
			error("Colour '" + type.getColour() + "': expected #RRGGBB or #RRGGBBAA in hexadecimal", type,
					CAT.getObjectType_Colour(), ReiIssueCodes.COLOUR);
		}
	}

	/**
	 * {@code speed A to B} on a type: how fast its people walk when their statements say nothing, as a route's
	 * speed would say it (RouteValidator); only people walk.
	 */
	@Check
	public void checkWalkingSpeed(ObjectType type) {
		if (!type.isSetWalkingSpeed() || !(type.eContainer() instanceof Catalogue)) {
			return;
		}
		if (type.getCategory() != ObjectCategory.HUMAN) {
			error("Only a human type walks: a " + type.getCategory().getLiteral().toLowerCase() + " type has no walking "
					+ "speed", type, CAT.getObjectType_WalkingSpeed(), ReiIssueCodes.TYPE_CATEGORY);
			return;
		}
		String problem = RouteValidator.speedProblem(type.getWalkingSpeed());
		if (problem != null) {
			error(problem, type, CAT.getObjectType_WalkingSpeed(), ReiIssueCodes.OUT_OF_RANGE);
		} else if (type.isSetWalkingSpeedTo()) {
			problem = RouteValidator.rangeProblem(type.getWalkingSpeed(), type.getWalkingSpeedTo());
			if (problem != null) {
				error(problem, type, CAT.getObjectType_WalkingSpeedTo(), ReiIssueCodes.OUT_OF_RANGE);
			}
		}
	}

	/**
	 * A polygon footprint (furniture only): at least 3 vertices, an area, no edge crossing or touching another
	 * (a simple polygon, convex or not), each error at what is wrong: the crossing edge's first vertex.
	 */
	@Check
	public void checkPolygon(ObjectType type) {
		if (!Polygons.isPolygon(type) || !(type.eContainer() instanceof Catalogue)) {
			return;
		}
		if (type.getCategory() != ObjectCategory.STATIC) {
			error("Only furniture stands on a polygon: a " + type.getCategory().getLiteral().toLowerCase()
					+ " type is a box or a cylinder", type, CAT.getObjectType_Shape(), ReiIssueCodes.TYPE_CATEGORY);
			return;
		}
		double[][] points = Polygons.points(type);
		if (points.length < 3) {
			error("A polygon has at least 3 vertices, got " + points.length + ": (x,y) in metres, e.g. (0,0) (1,0) "
					+ "(0,1)", type, CAT.getObjectType_Shape(), ReiIssueCodes.POLYGON);
			return;
		}
		if (Polygons.collinear(points)) {
			error("The polygon has no area: its vertices lie on one line", type, CAT.getObjectType_Shape(),
					ReiIssueCodes.POLYGON);
			return;
		}
		int[] crossing = Polygons.crossing(points);
		if (crossing != null) {
			int n = points.length;
			boolean repeat = points[crossing[0]][0] == points[crossing[1]][0]
					&& points[crossing[0]][1] == points[crossing[1]][1];
			String message = repeat
					? "Vertex " + (crossing[1] + 1) + " repeats vertex " + (crossing[0] + 1) + ": a polygon's edges "
							+ "must have a length"
					: "The polygon crosses itself: its edge from vertex " + (crossing[1] + 1) + " to vertex "
							+ ((crossing[1] + 1) % n + 1) + " meets the edge from vertex " + (crossing[0] + 1)
							+ " to vertex " + ((crossing[0] + 1) % n + 1) + " (the vertices go round the outline "
							+ "in order)";
			error(message, type.getVertices().get(crossing[1]), null, ReiIssueCodes.POLYGON);
			return;
		}
		if (Math.abs(Polygons.doubleArea(points)) / 2 < Polygons.MIN_AREA) {
			error("The polygon has no area: its vertices lie on one line", type, CAT.getObjectType_Shape(),
					ReiIssueCodes.POLYGON);
		}
	}

	@Check
	public void checkRobot(RobotType robot) {
		if (robot.getDescription() == null && robot.getSizeZ() > 0 && robot.getSizeZ() < MIN_ROBOT_HEIGHT) {
			error("A robot's body must be at least " + MIN_ROBOT_HEIGHT + " m high (its chassis sits above the wheels' "
					+ "ground clearance)", robot, CAT.getObjectType_SizeZ(), ReiIssueCodes.OUT_OF_RANGE);
		}
		positive(robot, CAT.getRobotType_WheelRadius(), "wheel radius");
		positive(robot, CAT.getRobotType_WheelSeparation(), "distance between the wheels");
		positive(robot, CAT.getRobotType_MaxLinearVelocity(), "top speed");
		positive(robot, CAT.getRobotType_MaxAngularVelocity(), "top turn rate");
	}

	/**
	 * A robot read from its URDF or xacro description: what Java can check here, the file being there and the
	 * catalogue entry saying what the description cannot (which link is the lidar). Whether the description reads
	 * (xacro, the URDF parser, the lidar's link existing) is the Python reader's to say, which {@code rei generate}
	 * runs and reports at this entry (docs/language.md#robots-from-descriptions).
	 */
	@Check
	public void checkDescription(RobotType robot) {
		if (robot.getDescription() == null) {
			if (robot.getLidar() != null && robot.getLidar().getLink() != null) {
				error("Only a robot read from a description has links: a box robot's lidar is placed by 'height'",
						robot.getLidar(), CAT.getLidar_Link(), ReiIssueCodes.ROBOT_DESCRIPTION);
			}
			return;
		}
		Path file = RobotDescriptions.file(robot);
		if (robot.getDescription().isBlank()) {
			error("The robot's description names no file: expected a URDF or xacro file's path", robot,
					CAT.getRobotType_Description(), ReiIssueCodes.ROBOT_DESCRIPTION);
		} else if (file == null || !Files.isRegularFile(file)) {
			error("Cannot read the robot's description '" + robot.getDescription() + "': no such file (paths are "
					+ "relative to this catalogue)", robot, CAT.getRobotType_Description(),
					ReiIssueCodes.ROBOT_DESCRIPTION);
		}
		Set<String> names = new HashSet<>();
		for (int i = 0; i < robot.getDescriptionArgNames().size(); i++) {
			if (!names.add(robot.getDescriptionArgNames().get(i))) {
				error("The xacro argument '" + robot.getDescriptionArgNames().get(i) + "' is given twice", robot,
						CAT.getRobotType_DescriptionArgNames(), i, ReiIssueCodes.ROBOT_DESCRIPTION);
			}
		}
		if (robot.getLidar() == null || robot.getLidar().getLink() == null) {
			error("A robot read from a description names its lidar's link: lidar link \"LINK\" (e.g. \"base_scan\")",
					robot, CAT.getRobotType_Description(), ReiIssueCodes.ROBOT_DESCRIPTION);
		} else if (!NodeModelUtils.findNodesForFeature(robot.getLidar(), CAT.getLidar_MountHeight()).isEmpty()) {
			error("The lidar's height comes from its link in the description: leave 'height' out", robot.getLidar(),
					CAT.getLidar_MountHeight(), ReiIssueCodes.ROBOT_DESCRIPTION);
		}
	}

	@Check
	public void checkLidar(Lidar lidar) {
		if (lidar.getBeams() < 1 || lidar.getBeams() > MAX_BEAMS) {
			error("A lidar has 1 to " + MAX_BEAMS + " beams, got " + lidar.getBeams(), lidar, CAT.getLidar_Beams(),
					ReiIssueCodes.OUT_OF_RANGE);
		}
		if (lidar.getRangeMin() < 0) {
			error("The lidar's shortest range must not be negative", lidar, CAT.getLidar_RangeMin(),
					ReiIssueCodes.OUT_OF_RANGE);
		} else if (!(lidar.getRangeMax() > lidar.getRangeMin())) {
			error("The lidar's longest range must be above its shortest (" + lidar.getRangeMin() + " m)", lidar,
					CAT.getLidar_RangeMax(), ReiIssueCodes.OUT_OF_RANGE);
		}
		if (!(lidar.getRate() > 0 && lidar.getRate() <= MAX_LIDAR_RATE)) {
			error("The lidar scans 0 to " + (int) MAX_LIDAR_RATE + " times a second (above 0), got " + lidar.getRate(),
					lidar, CAT.getLidar_Rate(), ReiIssueCodes.OUT_OF_RANGE);
		}
		positive(lidar, CAT.getLidar_MountHeight(), "lidar's mounting height");
	}

	private void positive(org.eclipse.emf.ecore.EObject element, EAttribute feature, String what) {
		if (!(((Number) element.eGet(feature)).doubleValue() > 0)) {
			error("The " + what + " must be above 0", element, feature, ReiIssueCodes.NON_POSITIVE);
		}
	}

	private void importError(TestCase testCase, CatalogueImports.Import i, String message, String code) {
		error(message, testCase, ContextPackage.Literals.TEST_CASE__CATALOGUE_IMPORTS, i.index(), code);
	}
}
