/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.rei.catalogue.CatalogueFactory;
import org.rei.catalogue.Inertia;
import org.rei.catalogue.Lidar;
import org.rei.catalogue.ObjectCategory;
import org.rei.catalogue.ObjectType;
import org.rei.catalogue.RobotType;
import org.rei.catalogue.Shape;
import org.rei.catalogue.util.Polygons;
import org.rei.context.Direction;
import org.rei.context.Floor;
import org.rei.context.PhysicalObject;
import org.rei.context.layout.Cell;
import org.rei.context.layout.FloorLayout;
import org.rei.runtime.ConcreteObject;

/**
 * What the templates call as {@code gen}: number and string rendering, and the few derived values (mass, inertia,
 * colour, cells) that are lookups or arithmetic better done once in Java than in template code.
 * One instance per generation run.
 */
public final class TemplateSupport {

	private static final Lidar DEFAULT_LIDAR = CatalogueFactory.eINSTANCE.createLidar();

	private final FloorLayout layout;
	private final Map<PhysicalObject, ConcreteObject> concrete;
	private final Map<ObjectType, String[]> colours = new IdentityHashMap<>();
	private final Map<String, String> meshes = new HashMap<>();
	private final Path outputDir;
	private final MapRoom mapRoom;
	private final RobotDescription description;

	TemplateSupport(FloorLayout layout, ConcreteMapping.Result model, Path outputDir, MapRoom mapRoom,
			RobotDescription description) throws GenerationException {
		this.description = description;
		this.layout = layout;
		this.mapRoom = mapRoom;
		this.concrete = model.concrete();
		this.outputDir = outputDir;
		for (ConcreteObject body : model.environment().getOwnedObjects()) {
			ObjectType type = body.getType();
			if (!colours.containsKey(type)) {
				colours.put(type, parseColour(type));
			}
		}
	}

	/** A number with at most 6 decimals and never an exponent. */
	public String num(double value) {
		return Numbers.format(value);
	}

	/** A JSON string literal, or {@code null}. */
	public String str(String value) {
		if (value == null) {
			return "null";
		}
		StringBuilder sb = new StringBuilder(value.length() + 2).append('"');
		for (int i = 0; i < value.length(); i++) {
			char c = value.charAt(i);
			switch (c) {
			case '"' -> sb.append("\\\"");
			case '\\' -> sb.append("\\\\");
			case '\n' -> sb.append("\\n");
			case '\r' -> sb.append("\\r");
			case '\t' -> sb.append("\\t");
			default -> {
				if (c < 0x20) {
					sb.append(String.format("\\u%04x", (int) c));
				} else {
					sb.append(c);
				}
			}
			}
		}
		return sb.append('"').toString();
	}

	/**
	 * The JSON string literal of an element's name, or {@code null}. Cheaper in templates than {@code x.name} for
	 * elements outside the template's models (catalogue types, context floors), which EOL reads reflectively.
	 */
	public String name(EObject element) {
		if (element == null) {
			return "null";
		}
		EStructuralFeature feature = element.eClass().getEStructuralFeature("name");
		return str(feature == null ? null : (String) element.eGet(feature));
	}

	/** Text escaped for an XML attribute or element; empty for {@code null}. */
	public String xml(String value) {
		if (value == null) {
			return "";
		}
		StringBuilder sb = new StringBuilder(value.length());
		for (int i = 0; i < value.length(); i++) {
			char c = value.charAt(i);
			switch (c) {
			case '<' -> sb.append("&lt;");
			case '>' -> sb.append("&gt;");
			case '&' -> sb.append("&amp;");
			case '"' -> sb.append("&quot;");
			case '\'' -> sb.append("&apos;");
			default -> sb.append(c);
			}
		}
		return sb.toString();
	}

	/** Whether the simulator must hold the body in place: floors, walls and furniture. */
	public boolean fixed(ConcreteObject body) {
		ObjectCategory c = body.getCategory();
		return c == ObjectCategory.FLOOR || c == ObjectCategory.WALL || c == ObjectCategory.STATIC
				|| body.getType().getMass() <= 0;
	}

	/** Mass in kg as the simulator gets it: 0 for fixed bodies. */
	public double mass(ConcreteObject body) {
		return fixed(body) ? 0 : body.getType().getMass();
	}

	/** Moment of inertia about x (0 for fixed bodies). */
	public double ixx(ConcreteObject body) {
		return inertia(body)[0];
	}

	/** Moment of inertia about y (0 for fixed bodies). */
	public double iyy(ConcreteObject body) {
		return inertia(body)[1];
	}

	/** Moment of inertia about z (0 for fixed bodies). */
	public double izz(ConcreteObject body) {
		return inertia(body)[2];
	}

	/** The catalogue's moments when it has them, else those of a solid box or cylinder of the body's size. */
	static double[] inertia(ConcreteObject body, double mass) {
		if (mass == 0) {
			return new double[3];
		}
		Inertia given = body.getType().getInertia();
		if (given != null) {
			return new double[] { given.getIxx(), given.getIyy(), given.getIzz() };
		}
		double x = body.getSizeX();
		double y = body.getSizeY();
		double z = body.getSizeZ();
		if (body.getType().getShape() == Shape.CYLINDER) {
			double r = x / 2;
			double side = mass / 12 * (3 * r * r + z * z);
			return new double[] { side, side, mass / 2 * r * r };
		}
		// boxes, and meshes by their bounding box
		return new double[] { mass / 12 * (y * y + z * z), mass / 12 * (x * x + z * z), mass / 12 * (x * x + y * y) };
	}

	private double[] inertia(ConcreteObject body) {
		return inertia(body, mass(body));
	}

	/** The type's colour as four numbers in 0..1 joined by {@code separator}. */
	public String rgba(ObjectType type, String separator) {
		String[] c = colours.get(type);
		if (c == null) {
			throw new IllegalArgumentException("type " + type.getName() + " is not used in this world");
		}
		return c[0] + separator + c[1] + separator + c[2] + separator + c[3];
	}

	/** Shape literal of a type: BOX, CYLINDER or MESH (BOX when unset). */
	public String shape(ObjectType type) {
		return (type.getShape() == null ? Shape.BOX : type.getShape()).getLiteral();
	}

	/**
	 * world.json's {@code footprint} of a POLYGON object (its vertices about its pose, the bounding box's centre,
	 * counter-clockwise: docs/artifacts.md); the template writes none for every other shape, so their lines stay as
	 * they were.
	 */
	public String footprint(ConcreteObject body) {
		if (!Polygons.isPolygon(body.getType())) {
			return "";
		}
		StringBuilder out = new StringBuilder("{\"type\": \"polygon\", \"points\": [");
		double[][] points = Polygons.centred(body.getType());
		for (int i = 0; i < points.length; i++) {
			out.append(i == 0 ? "" : ", ").append('[').append(num(points[i][0])).append(", ").append(num(points[i][1]))
					.append(']');
		}
		return out.append("]}").toString();
	}

	/** A type's x size; a POLYGON type's bounding box's. */
	public double typeSizeX(ObjectType type) {
		if (!Polygons.isPolygon(type)) {
			return type.getSizeX();
		}
		double[] b = Polygons.bounds(Polygons.points(type));
		return b[2] - b[0];
	}

	/** A type's y size; a POLYGON type's bounding box's. */
	public double typeSizeY(ObjectType type) {
		if (!Polygons.isPolygon(type)) {
			return type.getSizeY();
		}
		double[] b = Polygons.bounds(Polygons.points(type));
		return b[3] - b[1];
	}

	/** world.sdf's geometry of a POLYGON object: an SDF polyline of its footprint, its height high. */
	public String polyline(ConcreteObject body) {
		StringBuilder out = new StringBuilder("<polyline>");
		for (double[] p : Polygons.centred(body.getType())) {
			out.append("<point>").append(num(p[0])).append(' ').append(num(p[1])).append("</point>");
		}
		return out.append("<height>").append(num(body.getSizeZ())).append("</height></polyline>").toString();
	}

	/** Mesh file of a MESH type when the file exists (relative paths against the output folder), else null. */
	public String mesh(ObjectType type) {
		if (type.getShape() != Shape.MESH || type.getMesh() == null || type.getMesh().isBlank()) {
			return null;
		}
		return meshes.computeIfAbsent(type.getMesh(), m -> {
			try {
				return Files.isRegularFile(outputDir.resolve(m)) ? m : null;
			} catch (InvalidPathException e) {
				return null;
			}
		});
	}

	/** {@code [i, j]} cell of the floor a body stands on. */
	public String cell(ConcreteObject body) {
		Cell cell = layout.cellOf(body.getStandsOn()).orElseThrow();
		return "[" + cell.x() + ", " + cell.y() + "]";
	}

	/** JSON name of the neighbour on a side (top, right, bottom, left) of a floor, or {@code null}. */
	public String neighbour(ConcreteObject floorBody, String side) {
		var block = layout.neighbour(floorBody.getStandsOn(), Direction.get(side));
		return block == null ? "null" : str(block.getName());
	}

	/** Centre x of a floor. */
	public double x(Floor floor) {
		return layout.centreOf(floor)[0];
	}

	/** Centre y of a floor. */
	public double y(Floor floor) {
		return layout.centreOf(floor)[1];
	}

	/** Extent of the room along x (a map room: of its map). */
	public double width() {
		return mapRoom != null ? mapRoom.map().width() * mapRoom.map().resolution()
				: layout.columns() * layout.floorSize();
	}

	/** Extent of the room along y (a map room: of its map). */
	public double height() {
		return mapRoom != null ? mapRoom.map().height() * mapRoom.map().resolution()
				: layout.rows() * layout.floorSize();
	}

	/** The room's corner with the smallest x and y: a map room's map origin, else (0, 0). */
	public double originX() {
		return mapRoom != null ? mapRoom.map().originX() : 0;
	}

	/** See {@link #originX()}. */
	public double originY() {
		return mapRoom != null ? mapRoom.map().originY() : 0;
	}

	/** world.json's {@code map} member of a room from an occupancy map, {@code null} for another room. */
	public String map() {
		return mapRoom == null ? null : mapRoom.json();
	}

	/** The body an abstract object became. */
	public ConcreteObject concrete(PhysicalObject object) {
		return concrete.get(object);
	}

	/** What the robot's URDF or xacro description gives, {@code null} for a box robot. */
	public RobotDescription description() {
		return description;
	}

	/** The expanded description's file in the case folder. */
	public String descriptionFile() {
		return str(ArtifactGenerator.ROBOT_URDF);
	}

	/** The wheel radius: the description's wheel joints', else the catalogue entry's (or its default). */
	public double wheelRadius(ConcreteObject robot) {
		return description != null && description.wheelRadius() != null ? description.wheelRadius()
				: drive(robot).getWheelRadius();
	}

	/** The wheel separation: the description's wheel joints', else the catalogue entry's (or its default). */
	public double wheelSeparation(ConcreteObject robot) {
		return description != null && description.wheelSeparation() != null ? description.wheelSeparation()
				: drive(robot).getWheelSeparation();
	}

	/** The lidar's height: its link's in a description, else the catalogue entry's. */
	public double lidarHeight(ConcreteObject robot) {
		return description != null ? description.lidarZ() : lidar(robot).getMountHeight();
	}

	/** The robot's lidar: its type's, else the defaults of the catalogue metamodel. */
	public Lidar lidar(ConcreteObject robot) {
		return robot.getType() instanceof RobotType r && r.getLidar() != null ? r.getLidar() : DEFAULT_LIDAR;
	}

	/**
	 * world.json's {@code drive.kind} member, with its leading comma, for a robot whose drive is not the default
	 * (differential) one; empty otherwise, so a differential robot's world.json stays as it always was.
	 */
	public String driveKind(ConcreteObject robot) {
		org.rei.catalogue.Drive kind = drive(robot).getDrive();
		return kind == org.rei.catalogue.Drive.DIFFERENTIAL ? "" : ", \"kind\": " + str(kind.getLiteral());
	}

	/** The robot's type as a robot type (drive parameters), or a default one. */
	public RobotType drive(ConcreteObject robot) {
		return robot.getType() instanceof RobotType r ? r : DefaultRobot.TYPE;
	}

	/** Catalogue metamodel defaults for a robot type without drive parameters. */
	private static final class DefaultRobot {
		static final RobotType TYPE = CatalogueFactory.eINSTANCE.createRobotType();
	}

	private static String[] parseColour(ObjectType type) throws GenerationException {
		String colour = type.getColour() == null ? "#808080" : type.getColour().trim();
		if (!colour.matches("#(\\p{XDigit}{6}|\\p{XDigit}{8})")) {
			throw new GenerationException("type " + type.getName() + ": colour must be #RRGGBB or #RRGGBBAA, not " + colour);
		}
		String[] rgba = new String[4];
		for (int i = 0; i < 4; i++) {
			int channel = 1 + 2 * i < colour.length() ? Integer.parseInt(colour.substring(1 + 2 * i, 3 + 2 * i), 16) : 255;
			rgba[i] = Numbers.format(channel / 255.0);
		}
		return rgba;
	}
}
