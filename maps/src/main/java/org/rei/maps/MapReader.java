/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import java.io.IOException;
import java.io.StringReader;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.math.MathContext;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.Yaml;
import org.yaml.snakeyaml.constructor.SafeConstructor;
import org.yaml.snakeyaml.error.Mark;
import org.yaml.snakeyaml.error.MarkedYAMLException;
import org.yaml.snakeyaml.error.YAMLException;
import org.yaml.snakeyaml.nodes.MappingNode;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.NodeTuple;
import org.yaml.snakeyaml.nodes.ScalarNode;

/**
 * Reads a ROS {@code map_server} YAML file and its image into the grid {@code map_server} would publish, with the
 * arithmetic of Nav2's {@code map_io.cpp} ({@code loadMapYaml}, {@code loadMapFromFile}) as the Python side's
 * {@code rei.maps.occupancy} has it:
 * <ul>
 * <li>{@code occ = shade} when {@code negate}, else {@code 1 - shade} (the shade is {@link MapImages}'; in
 * {@code trinary} mode an alpha channel is averaged in with the three colour channels);</li>
 * <li>{@code trinary}: {@code occupied_thresh < occ} is 100, else {@code occ < free_thresh} is 0, else -1;</li>
 * <li>{@code scale}: a pixel that is not opaque is -1, else as {@code trinary} except that the values between the
 * thresholds become {@code rint((occ - free_thresh) / (occupied_thresh - free_thresh) * 100)};</li>
 * <li>{@code raw}: {@code round(shade * 255)} when within 0..100, else -1 ({@code negate} does not apply).</li>
 * </ul>
 * Every problem is a {@link MapException} at the YAML line and column of the field concerned.
 */
public final class MapReader {

	/** A number as Python's {@code float()} reads text (YAML 1.1 reads {@code 1e-2} as text, not a number). */
	private static final Pattern PY_FLOAT = Pattern.compile(
			"\\s*[+-]?((\\d(_?\\d)*)?\\.?\\d(_?\\d)*([eE][+-]?\\d(_?\\d)*)?|\\d(_?\\d)*\\.|inf(inity)?|nan)\\s*",
			Pattern.CASE_INSENSITIVE);

	private MapReader() {
	}

	/** Reads the map afresh (see {@link MapCache} for the cached form). */
	public static OccupancyMap read(Path yaml) throws MapException {
		Fields fields = new Fields(yaml);

		Object imageName = fields.value("image");
		if (!(imageName instanceof String name) || name.isBlank()) {
			throw fields.error("image", "expected the image file's name, got " + repr(imageName));
		}
		Path named = Path.of(name);
		Path image = named.isAbsolute() ? named : yaml.toAbsolutePath().getParent().resolve(name);

		double resolution = fields.number("resolution");
		if (resolution <= 0) {
			throw fields.error("resolution", "expected metres per cell above 0, got " + g(resolution));
		}

		Object origin = fields.value("origin");
		if (!(origin instanceof List<?> xyz) || xyz.size() != 3
				|| xyz.stream().anyMatch(v -> !(v instanceof Number) || !Double.isFinite(((Number) v).doubleValue()))) {
			throw fields.error("origin", "expected [x, y, yaw], three numbers, got " + repr(origin));
		}
		double yaw = ((Number) xyz.get(2)).doubleValue();
		if (yaw != 0) {
			// REI rooms are axis-aligned; a rotated map would need every floor and wall rotated with it.
			throw fields.error("origin",
					"a yaw of " + g(yaw) + " is not supported: REI rooms are axis-aligned (use 0)");
		}

		double freeThresh = fields.number("free_thresh");
		double occupiedThresh = fields.number("occupied_thresh");
		for (String threshold : List.of("free_thresh", "occupied_thresh")) {
			double value = threshold.equals("free_thresh") ? freeThresh : occupiedThresh;
			if (!(0.0 <= value && value <= 1.0)) {
				throw fields.error(threshold, "expected a fraction within 0..1, got " + g(value));
			}
		}
		if (!(freeThresh < occupiedThresh)) {
			throw fields.error("free_thresh",
					g(freeThresh) + " must be below occupied_thresh " + g(occupiedThresh));
		}

		Object mode = fields.has("mode") ? fields.value("mode") : "trinary"; // Nav2's default
		if (!OccupancyMap.MODES.contains(mode)) {
			throw fields.error("mode", "expected one of " + String.join(", ", OccupancyMap.MODES) + ", got "
					+ repr(mode));
		}

		Object negate = fields.value("negate");
		boolean negated;
		if (negate instanceof Boolean b) {
			negated = b;
		} else if (negate instanceof Integer i && (i == 0 || i == 1)) {
			negated = i == 1;
		} else {
			throw fields.error("negate", "expected 0, 1, true or false, got " + repr(negate));
		}

		Cells cells = new Cells((String) mode, negated, occupiedThresh, freeThresh);
		MapImages.read(image, detail -> {
			MapException e = fields.error("image", detail);
			return new MapException(e.file(), e.line(), e.column(), e.field(), e.detail(), image);
		}, cells);
		Node imageNode = fields.nodes.get("image");
		// marks count code points; the copy's YAML cuts the text by chars
		int start = fields.text.offsetByCodePoints(0, imageNode.getStartMark().getIndex());
		int end = fields.text.offsetByCodePoints(0, imageNode.getEndMark().getIndex());
		return new OccupancyMap(yaml, image, fields.text, start, end, resolution, ((Number) xyz.get(0)).doubleValue(),
				((Number) xyz.get(1)).doubleValue(), negated, occupiedThresh, freeThresh, (String) mode,
				cells.width, cells.height, cells.grid);
	}

	/**
	 * Nav2's per-pixel arithmetic, row by row as the image is read: the grid's row 0 is the image's last row (the
	 * map's bottom). Only the grid is kept, a byte per cell.
	 */
	private static final class Cells implements MapImages.Rows {
		private final String mode;
		private final boolean negate;
		private final double occupiedThresh;
		private final double freeThresh;
		int width;
		int height;
		byte[] grid;

		Cells(String mode, boolean negate, double occupiedThresh, double freeThresh) {
			this.mode = mode;
			this.negate = negate;
			this.occupiedThresh = occupiedThresh;
			this.freeThresh = freeThresh;
		}

		@Override
		public void start(int w, int h) {
			width = w;
			height = h;
			grid = new byte[w * h]; // at most OccupancyMap.MAX_CELLS, checked from the image's header
		}

		@Override
		public void row(int row, double[] shade, double[] alpha) {
			int target = (height - 1 - row) * width;
			for (int col = 0; col < width; col++) {
				grid[target + col] = cell(shade[col], alpha == null ? -1 : alpha[col]);
			}
		}

		/** One pixel; {@code alpha} below 0: the image has none. */
		private byte cell(double shade, double alpha) {
			if (mode.equals("raw")) {
				double value = Math.floor(shade * 255 + 0.5); // std::round: half away from zero (values >= 0)
				return value >= OccupancyMap.FREE && value <= OccupancyMap.OCCUPIED ? (byte) value
						: OccupancyMap.UNKNOWN;
			}
			if (mode.equals("trinary") && alpha >= 0) {
				shade = (shade * 3 + alpha) / 4; // the alpha averaged in with the colour channels
			}
			double occ = negate ? shade : 1.0 - shade;
			byte cell;
			if (occupiedThresh < occ) {
				cell = OccupancyMap.OCCUPIED;
			} else if (occ < freeThresh) {
				cell = OccupancyMap.FREE;
			} else if (mode.equals("trinary")) {
				cell = OccupancyMap.UNKNOWN;
			} else {
				cell = (byte) Math.rint((occ - freeThresh) / (occupiedThresh - freeThresh) * 100.0);
			}
			if (mode.equals("scale") && alpha >= 0 && alpha < 1.0) {
				cell = OccupancyMap.UNKNOWN;
			}
			return cell;
		}
	}

	/** The YAML's top-level mapping, each value with the position of its node. */
	private static final class Fields {
		final Path path;
		final String text;
		final Map<String, Node> nodes = new LinkedHashMap<>();
		final int[] rootMark;
		private final Values values = new Values();

		Fields(Path path) throws MapException {
			this.path = path;
			try {
				text = StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(Files.readAllBytes(path)))
						.toString();
			} catch (CharacterCodingException e) {
				throw new MapException(path, 1, 1, "file", "cannot read the map file: not UTF-8 text");
			} catch (IOException e) {
				throw new MapException(path, 1, 1, "file", "cannot read the map file: " + describe(e));
			}
			Node root;
			try {
				root = new Yaml(new SafeConstructor(new LoaderOptions())).compose(new StringReader(text));
			} catch (MarkedYAMLException e) {
				Mark mark = e.getProblemMark() != null ? e.getProblemMark() : e.getContextMark();
				throw new MapException(path, mark == null ? 1 : mark.getLine() + 1,
						mark == null ? 1 : mark.getColumn() + 1, "file", "not valid YAML: " + e.getProblem());
			} catch (YAMLException e) {
				throw new MapException(path, 1, 1, "file", "not valid YAML: " + e.getMessage());
			}
			rootMark = root == null ? new int[] { 1, 1 } : position(root);
			if (!(root instanceof MappingNode mapping)) {
				throw new MapException(path, rootMark[0], rootMark[1], "file",
						"expected a mapping of map_server fields");
			}
			for (NodeTuple entry : mapping.getValue()) {
				Node key = entry.getKeyNode();
				String name = key instanceof ScalarNode scalar ? String.valueOf(constructed(key)) : "None";
				if (nodes.containsKey(name)) {
					int[] at = position(key);
					throw new MapException(path, at[0], at[1], "file", "'" + name + "' is given twice");
				}
				nodes.put(name, entry.getValueNode());
			}
		}

		private Object constructed(Node node) throws MapException {
			try {
				return values.of(node);
			} catch (YAMLException e) {
				int[] at = position(node);
				throw new MapException(path, at[0], at[1], "file", "not a valid value: " + e.getMessage());
			}
		}

		boolean has(String name) {
			return nodes.containsKey(name);
		}

		MapException error(String name, String message) {
			Node node = nodes.get(name);
			int[] at = node != null ? position(node) : rootMark;
			return new MapException(path, at[0], at[1], name, message);
		}

		Object value(String name) throws MapException {
			Node node = nodes.get(name);
			if (node == null) {
				throw new MapException(path, rootMark[0], rootMark[1], name, "missing (map_server requires it)");
			}
			try {
				return values.of(node);
			} catch (YAMLException e) {
				throw error(name, "not a valid value: " + e.getMessage());
			}
		}

		/** A finite number, also YAML 1.1's {@code 1e-2} (text there), never a boolean. */
		double number(String name) throws MapException {
			Object found = value(name);
			Double number = null;
			if (found instanceof String s && PY_FLOAT.matcher(s).matches()) {
				number = Double.parseDouble(s.strip().replace("_", "").replaceAll("(?i)inf(inity)?", "Infinity")
						.replaceAll("(?i)nan", "NaN"));
			} else if (found instanceof Number n && !(n instanceof BigInteger big && big.bitLength() > 1023)) {
				number = n.doubleValue();
			}
			if (number == null || !Double.isFinite(number)) {
				throw error(name, "expected a number, got " + repr(found));
			}
			return number;
		}
	}

	/** SnakeYAML's safe constructor for one node at a time (values of YAML 1.1's safe types, as PyYAML's). */
	private static final class Values extends SafeConstructor {
		Values() {
			super(new LoaderOptions());
		}

		Object of(Node node) {
			return constructObject(node);
		}
	}

	private static int[] position(Node node) {
		return new int[] { node.getStartMark().getLine() + 1, node.getStartMark().getColumn() + 1 };
	}

	private static String describe(IOException e) {
		if (e instanceof java.nio.file.NoSuchFileException) {
			return "No such file or directory: '" + e.getMessage() + "'";
		}
		return e.getMessage() != null ? e.getMessage() : e.toString();
	}

	/** A value as Python's {@code repr} writes it, so that messages read as the Python side's. */
	static String repr(Object value) {
		if (value == null) {
			return "None";
		}
		if (value instanceof Boolean b) {
			return b ? "True" : "False";
		}
		if (value instanceof String s) {
			return "'" + s.replace("\\", "\\\\").replace("'", "\\'") + "'";
		}
		if (value instanceof List<?> list) {
			return list.stream().map(MapReader::repr).collect(Collectors.joining(", ", "[", "]"));
		}
		if (value instanceof Map<?, ?> map) {
			return map.entrySet().stream().map(e -> repr(e.getKey()) + ": " + repr(e.getValue()))
					.collect(Collectors.joining(", ", "{", "}"));
		}
		return String.valueOf(value);
	}

	/** A number as Python's {@code format(x, 'g')}: six significant digits, no trailing zeros. */
	static String g(double value) {
		if (!Double.isFinite(value)) {
			return Double.isNaN(value) ? "nan" : value > 0 ? "inf" : "-inf";
		}
		if (value == 0) {
			return 1 / value < 0 ? "-0" : "0";
		}
		BigDecimal rounded = new BigDecimal(value).round(new MathContext(6));
		int exponent = rounded.precision() - rounded.scale() - 1;
		if (exponent < -4 || exponent >= 6) {
			String mantissa = rounded.movePointLeft(exponent).stripTrailingZeros().toPlainString();
			return mantissa + "e" + (exponent < 0 ? "-" : "+") + String.format("%02d", Math.abs(exponent));
		}
		return rounded.stripTrailingZeros().toPlainString();
	}
}
