/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.server;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;

import org.rei.context.Direction;
import org.rei.dsl.edit.EditOperation;
import org.rei.dsl.edit.EditOperation.AddCrowd;
import org.rei.dsl.edit.EditOperation.AddDynamic;
import org.rei.dsl.edit.EditOperation.AddFloor;
import org.rei.dsl.edit.EditOperation.AddGoal;
import org.rei.dsl.edit.EditOperation.AddHuman;
import org.rei.dsl.edit.EditOperation.AddObject;
import org.rei.dsl.edit.EditOperation.AddWall;
import org.rei.dsl.edit.EditOperation.DeleteObject;
import org.rei.dsl.edit.EditOperation.MoveGoal;
import org.rei.dsl.edit.EditOperation.MoveObject;
import org.rei.dsl.edit.EditOperation.RemoveFloor;
import org.rei.dsl.edit.EditOperation.RemoveGoal;
import org.rei.dsl.edit.EditOperation.RemoveWall;
import org.rei.dsl.edit.EditOperation.RotateObject;
import org.rei.dsl.edit.EditOperation.SetCrowd;
import org.rei.dsl.edit.EditOperation.SetRoute;
import org.rei.dsl.edit.EditOperation.SetTrajectory;
import org.rei.dsl.edit.EditOperation.Stop;
import org.rei.dsl.edit.EditOperation.Waypoint;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The protocol's operations (docs/room-editor.md, "Operations") as {@link EditOperation}s: {@code op} names the
 * record in camelCase, the other fields are its components by name. Every field is required and checked for its
 * JSON type except {@code addHuman}'s {@code type} and {@code addGoal}'s {@code timeoutSeconds}, which may be null
 * or absent; fields the operation does not have are ignored. Sides and neighbour keys are the grammar's keywords.
 */
final class OperationDecoder {

	/** The protocol's side names onto the metamodel's directions (TOP for "top", ...). */
	private static final Map<String, Direction> SIDES = Protocol.SIDES.stream()
			.collect(Collectors.toUnmodifiableMap(side -> side, side -> Direction.valueOf(side.toUpperCase(Locale.ROOT))));

	private OperationDecoder() {
	}

	/** The operations of an apply request, all decoded before any is applied. */
	static List<EditOperation> decodeAll(JsonNode operations) throws RequestException {
		if (operations == null || operations.isNull() || operations.isMissingNode()) {
			throw new RequestException("apply needs 'operations': a list of operations, e.g. [{\"op\": \"moveObject\", "
					+ "\"name\": \"table1\", \"floor\": \"F_3_3\"}]");
		}
		if (!operations.isArray()) {
			throw new RequestException("'operations' must be a list of operations, got " + describe(operations));
		}
		if (operations.isEmpty()) {
			throw new RequestException("'operations' is empty: apply needs one operation at least");
		}
		List<EditOperation> result = new ArrayList<>();
		for (int i = 0; i < operations.size(); i++) {
			result.add(decode(operations.get(i), i));
		}
		return result;
	}

	static EditOperation decode(JsonNode node, int index) throws RequestException {
		if (!node.isObject()) {
			throw new RequestException("operation " + index + " must be an object {\"op\": ..., ...}, got "
					+ describe(node));
		}
		JsonNode op = node.get("op");
		if (op == null || !op.isTextual()) {
			throw new RequestException("operation " + index + " has no 'op' (its kind, one of " + String.join(", ", Protocol.OPERATIONS)
					+ ")" + (op == null ? "" : ", got " + describe(op)));
		}
		Fields f = new Fields(node, "operation " + index + " (" + op.asText() + ")");
		switch (op.asText()) {
		case "moveObject":
			return new MoveObject(f.string("name"), f.string("floor"));
		case "rotateObject":
			return new RotateObject(f.string("name"), f.number("yawDegrees"));
		case "addObject":
			return new AddObject(f.string("name"), f.string("type"), f.string("floor"));
		case "deleteObject":
			return new DeleteObject(f.string("name"));
		case "addHuman":
			return new AddHuman(f.string("name"), f.optionalString("type"), f.waypoints("points"), f.bool("loop"));
		case "addDynamic":
			return new AddDynamic(f.string("name"), f.string("type"), f.waypoints("points"), f.bool("loop"));
		case "addFloor":
			return new AddFloor(f.string("name"), f.neighbours("neighbours"));
		case "removeFloor":
			return new RemoveFloor(f.string("name"));
		case "addWall":
			return new AddWall(f.string("name"), f.string("floor"), f.side("side"));
		case "removeWall":
			return new RemoveWall(f.string("name"));
		case "setTrajectory":
			return new SetTrajectory(f.string("name"), f.waypoints("points"), f.bool("loop"));
		case "setRoute":
			return new SetRoute(f.string("name"), f.stops("stops"), f.number("speed"), f.number("start"),
					f.bool("loop"), f.string("behaviour"));
		case "addCrowd":
			return new AddCrowd(f.string("name"), f.optionalString("type"), f.integer("count"), f.floors("from"),
					f.floors("to"), f.optionalNumber("rate"));
		case "setCrowd":
			return new SetCrowd(f.string("name"), f.integer("count"), f.floors("from"), f.floors("to"),
					f.optionalNumber("rate"));
		case "addGoal":
			return new AddGoal(f.string("floor"), f.integer("index"), f.optionalNumber("timeoutSeconds"));
		case "removeGoal":
			return new RemoveGoal(f.integer("index"));
		case "moveGoal":
			return new MoveGoal(f.integer("from"), f.integer("to"));
		default:
			throw new RequestException("operation " + index + ": unknown op '" + op.asText() + "', expected one of "
					+ String.join(", ", Protocol.OPERATIONS));
		}
	}

	/** The fields of one operation, each read with the message that names the operation and the field. */
	private static final class Fields {
		private final JsonNode node;
		private final String where;

		Fields(JsonNode node, String where) {
			this.node = node;
			this.where = where;
		}

		private JsonNode required(String field, String what) throws RequestException {
			JsonNode value = node.get(field);
			if (value == null || value.isNull()) {
				throw new RequestException(where + ": missing field '" + field + "' (" + what + ")");
			}
			return value;
		}

		String string(String field) throws RequestException {
			JsonNode value = required(field, "a string");
			return text(field, value);
		}

		String optionalString(String field) throws RequestException {
			JsonNode value = node.get(field);
			return value == null || value.isNull() ? null : text(field, value);
		}

		private String text(String field, JsonNode value) throws RequestException {
			if (!value.isTextual()) {
				throw new RequestException(where + ": '" + field + "' must be a string, got " + describe(value));
			}
			return value.asText();
		}

		double number(String field) throws RequestException {
			return number(field, required(field, "a number"));
		}

		Double optionalNumber(String field) throws RequestException {
			JsonNode value = node.get(field);
			return value == null || value.isNull() ? null : number(field, value);
		}

		private double number(String field, JsonNode value) throws RequestException {
			if (!value.isNumber() || !Double.isFinite(value.doubleValue())) {
				throw new RequestException(where + ": '" + field + "' must be a number, got " + describe(value));
			}
			return value.doubleValue();
		}

		int integer(String field) throws RequestException {
			JsonNode value = required(field, "a whole number");
			boolean whole = value.isIntegralNumber() ? value.canConvertToInt()
					: value.isNumber() && value.doubleValue() == Math.rint(value.doubleValue())
							&& Math.abs(value.doubleValue()) <= Integer.MAX_VALUE;
			if (!whole) {
				throw new RequestException(where + ": '" + field + "' must be a whole number, got "
						+ describe(value));
			}
			return (int) value.doubleValue();
		}

		boolean bool(String field) throws RequestException {
			JsonNode value = required(field, "true or false");
			if (!value.isBoolean()) {
				throw new RequestException(where + ": '" + field + "' must be true or false, got " + describe(value));
			}
			return value.booleanValue();
		}

		Direction side(String field) throws RequestException {
			return side(string(field), "'" + field + "'");
		}

		private Direction side(String keyword, String what) throws RequestException {
			Direction side = SIDES.get(keyword);
			if (side == null) {
				throw new RequestException(where + ": " + what + " is '" + keyword + "', expected top, right, "
						+ "bottom or left");
			}
			return side;
		}

		Map<Direction, String> neighbours(String field) throws RequestException {
			JsonNode value = required(field, "an object of sides and floor or wall names, e.g. {\"left\": \"B\"}");
			if (!value.isObject()) {
				throw new RequestException(where + ": '" + field + "' must be an object of sides and names, e.g. "
						+ "{\"left\": \"B\"}, got " + describe(value));
			}
			Map<Direction, String> result = new EnumMap<>(Direction.class);
			for (Iterator<Map.Entry<String, JsonNode>> it = value.fields(); it.hasNext();) {
				Map.Entry<String, JsonNode> entry = it.next();
				Direction side = side(entry.getKey(), "a key of '" + field + "'");
				if (!entry.getValue().isTextual()) {
					throw new RequestException(where + ": '" + field + "." + entry.getKey() + "' must be a name, got "
							+ describe(entry.getValue()));
				}
				result.put(side, entry.getValue().asText());
			}
			return result;
		}

		List<Waypoint> waypoints(String field) throws RequestException {
			JsonNode value = required(field, "a list of {\"floor\": NAME, \"seconds\": TIME}");
			if (!value.isArray()) {
				throw new RequestException(where + ": '" + field + "' must be a list of {\"floor\": NAME, "
						+ "\"seconds\": TIME}, got " + describe(value));
			}
			List<Waypoint> points = new ArrayList<>();
			for (int i = 0; i < value.size(); i++) {
				JsonNode point = value.get(i);
				Fields p = new Fields(point, where + ", " + field + "[" + i + "]");
				if (!point.isObject()) {
					throw new RequestException(p.where + ": must be {\"floor\": NAME, \"seconds\": TIME}, got "
							+ describe(point));
				}
				points.add(new Waypoint(p.string("floor"), p.number("seconds")));
			}
			return points;
		}

		/** A list of floor names (a crowd's area); an empty one is the editor's to refuse, with its message. */
		List<String> floors(String field) throws RequestException {
			JsonNode value = required(field, "a list of floor names");
			if (!value.isArray()) {
				throw new RequestException(where + ": '" + field + "' must be a list of floor names, got "
						+ describe(value));
			}
			List<String> floors = new ArrayList<>();
			for (int i = 0; i < value.size(); i++) {
				if (!value.get(i).isTextual()) {
					throw new RequestException(where + ", " + field + "[" + i + "]: must be a floor name, got "
							+ describe(value.get(i)));
				}
				floors.add(value.get(i).asText());
			}
			return floors;
		}

		List<Stop> stops(String field) throws RequestException {
			JsonNode value = required(field, "a list of {\"floor\": NAME, \"waitSeconds\": TIME}");
			if (!value.isArray()) {
				throw new RequestException(where + ": '" + field + "' must be a list of {\"floor\": NAME, "
						+ "\"waitSeconds\": TIME}, got " + describe(value));
			}
			List<Stop> stops = new ArrayList<>();
			for (int i = 0; i < value.size(); i++) {
				JsonNode stop = value.get(i);
				Fields s = new Fields(stop, where + ", " + field + "[" + i + "]");
				if (!stop.isObject()) {
					throw new RequestException(s.where + ": must be {\"floor\": NAME, \"waitSeconds\": TIME}, got "
							+ describe(stop));
				}
				stops.add(new Stop(s.string("floor"), s.number("waitSeconds")));
			}
			return stops;
		}
	}

	/** A JSON value for a message, cut short. */
	static String describe(JsonNode value) {
		String text = value.toString();
		return text.length() > 60 ? text.substring(0, 57) + "..." : text;
	}
}
