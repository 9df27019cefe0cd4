/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.wire;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.msgpack.core.MessageFormat;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.ValueType;
import org.rei.vepl.runtime.MissionEvent;

/**
 * Decodes state and mission messages straight from msgpack bytes (no intermediate tree: this runs for every
 * message). Keys may come in any order, unknown keys are skipped, optional keys may be absent; every real number
 * is read as a double whether it was packed as float or integer. Anything else is a
 * {@link MalformedMessageException} naming the problem.
 */
public final class WireDecoder {

	// array headers come from the wire: a few bytes may claim billions of elements, so never allocate by them
	private static final int CAPACITY = 1024;
	private static final int MAX_REALS = 1 << 16;
	private static final Set<String> EVENTS = Set.copyOf(MissionEvent.ALL);

	private WireDecoder() {
	}

	public static StateMessage decodeState(byte[] data) throws MalformedMessageException {
		return decodeState(data, 0, data.length);
	}

	public static StateMessage decodeState(byte[] data, int offset, int length) throws MalformedMessageException {
		return decodeState(data, offset, length, null);
	}

	/**
	 * Decodes a state message; with a {@link StaticEntryCache}, {@code objects} entries that repeat the kept bytes
	 * of an unchanged static obstacle are skipped without decoding and left out of the message's object list.
	 * Hand the result to the owner of the cache ({@code StaticEntryCache.applied}) before decoding the next one.
	 */
	public static StateMessage decodeState(byte[] data, int offset, int length, StaticEntryCache cache)
			throws MalformedMessageException {
		if (cache != null) {
			cache.begin(data);
		}
		try (MessageUnpacker in = MessagePack.newDefaultUnpacker(data, offset, length)) {
			StateMessage m = state(in, new Frame(data, offset, offset + length, cache));
			if (cache != null) {
				cache.end(m);
			}
			return m;
		} catch (IOException | RuntimeException e) {
			throw new MalformedMessageException("undecodable-state", String.valueOf(e.getMessage()), e);
		}
	}

	/** Where the unpacker reads: absolute positions in {@code data} for the static-entry cache. */
	private record Frame(byte[] data, int offset, int limit, StaticEntryCache cache) {
		int position(MessageUnpacker in) {
			return offset + (int) in.getTotalReadBytes();
		}
	}

	public static MissionMessage decodeMission(byte[] data) throws MalformedMessageException {
		return decodeMission(data, 0, data.length);
	}

	public static MissionMessage decodeMission(byte[] data, int offset, int length) throws MalformedMessageException {
		try (MessageUnpacker in = MessagePack.newDefaultUnpacker(data, offset, length)) {
			return mission(in);
		} catch (IOException | RuntimeException e) {
			throw new MalformedMessageException("undecodable-mission", String.valueOf(e.getMessage()), e);
		}
	}

	private static StateMessage state(MessageUnpacker in, Frame frame) throws IOException, MalformedMessageException {
		int n = mapHeader(in, "state");
		long seq = -1;
		double t = Double.NaN;
		boolean full = false;
		List<ObjectState> objects = null;
		RobotState robot = null;
		List<String[]> contacts = null;
		for (int i = 0; i < n; i++) {
			String key = in.unpackString();
			switch (key) {
			case "seq" -> seq = integer(in, "seq");
			case "t" -> t = real(in, "t");
			case "full" -> full = in.getNextFormat() == MessageFormat.NIL ? nilFalse(in) : in.unpackBoolean();
			case "objects" -> objects = objects(in, frame);
			case "robot" -> robot = robot(in);
			case "contacts" -> contacts = contacts(in);
			default -> in.skipValue();
			}
		}
		require(seq >= 0, "missing-field", "state without seq");
		require(Double.isFinite(t), "missing-field", "state without a finite t");
		require(objects != null, "missing-field", "state without objects");
		require(robot != null, "missing-field", "state without robot");
		return new StateMessage(seq, t, full, objects, robot, contacts);
	}

	private static boolean nilFalse(MessageUnpacker in) throws IOException {
		in.unpackNil();
		return false;
	}

	private static List<ObjectState> objects(MessageUnpacker in, Frame frame)
			throws IOException, MalformedMessageException {
		int n = arrayHeader(in, "objects");
		StaticEntryCache cache = frame.cache();
		List<ObjectState> out = new ArrayList<>(Math.min(n, cache != null ? 64 : CAPACITY));
		double[] pose = new double[4];
		double[] twist = new double[3];
		int i = 0;
		while (i < n) {
			if (cache != null) {
				// a run of entries equal to the kept bytes of unchanged statics: step over them in one go
				int pos = frame.position(in);
				int run = 0;
				for (int len; i < n && (len = cache.unchanged(i, frame.data(), pos + run, frame.limit())) > 0; i++) {
					run += len;
				}
				if (run > 0) {
					in.readPayloadAsReference(run);
					continue;
				}
			}
			int start = cache != null ? frame.position(in) : 0;
			ObjectState o = object(in, pose, twist);
			if (cache != null) {
				cache.decoded(i, start, frame.position(in) - start, o.name());
			}
			out.add(o);
			i++;
		}
		return out;
	}

	private static ObjectState object(MessageUnpacker in, double[] pose, double[] twist)
			throws IOException, MalformedMessageException {
		int m = mapHeader(in, "object");
		String name = null;
		String type = null;
		boolean hasPose = false;
		twist[0] = twist[1] = twist[2] = 0;
		for (int k = 0; k < m; k++) {
			String key = in.unpackString();
			switch (key) {
			case "name" -> name = string(in, "object name");
			case "type" -> type = string(in, "object type");
			case "pose" -> {
				reals(in, pose, "object pose");
				hasPose = true;
			}
			case "twist" -> reals(in, twist, "object twist");
			default -> in.skipValue();
			}
		}
		require(name != null && hasPose, "missing-field", "object without name or pose");
		return new ObjectState(name, type, pose[0], pose[1], pose[2], pose[3], twist[0], twist[1], twist[2]);
	}

	private static RobotState robot(MessageUnpacker in) throws IOException, MalformedMessageException {
		int m = mapHeader(in, "robot");
		String name = null;
		double[] pose = null;
		double[] twist = new double[3];
		double[] odom = null;
		double laserMin = Double.NaN;
		double laserClearance = Double.NaN;
		double[] ranges = null;
		String nav = null;
		for (int k = 0; k < m; k++) {
			String key = in.unpackString();
			switch (key) {
			case "name" -> name = string(in, "robot name");
			case "pose" -> {
				pose = new double[4];
				reals(in, pose, "robot pose");
			}
			case "twist" -> reals(in, twist, "robot twist");
			case "odom" -> {
				if (in.getNextFormat() == MessageFormat.NIL) {
					in.unpackNil();
				} else {
					odom = new double[3];
					reals(in, odom, "odom");
				}
			}
			case "laser_min" -> laserMin = in.getNextFormat() == MessageFormat.NIL ? nilNaN(in) : real(in, "laser_min");
			case "laser_clearance" -> laserClearance = in.getNextFormat() == MessageFormat.NIL ? nilNaN(in)
					: real(in, "laser_clearance");
			case "laser_ranges" -> ranges = realArray(in, "laser_ranges");
			case "nav_state" -> nav = in.getNextFormat() == MessageFormat.NIL ? nilNull(in) : string(in, "nav_state");
			default -> in.skipValue();
			}
		}
		require(name != null && pose != null, "missing-field", "robot without name or pose");
		return new RobotState(name, pose[0], pose[1], pose[2], pose[3], twist[0], twist[1], twist[2], odom, laserMin,
				ranges, nav, laserClearance);
	}

	private static double nilNaN(MessageUnpacker in) throws IOException {
		in.unpackNil();
		return Double.NaN;
	}

	private static String nilNull(MessageUnpacker in) throws IOException {
		in.unpackNil();
		return null;
	}

	private static List<String[]> contacts(MessageUnpacker in) throws IOException, MalformedMessageException {
		if (in.getNextFormat() == MessageFormat.NIL) {
			in.unpackNil();
			return null;
		}
		int n = arrayHeader(in, "contacts");
		List<String[]> out = new ArrayList<>(Math.min(n, CAPACITY));
		for (int i = 0; i < n; i++) {
			int m = arrayHeader(in, "contact");
			require(m == 2, "bad-field", "a contact is a pair of names, got " + m + " elements");
			out.add(new String[] { string(in, "contact"), string(in, "contact") });
		}
		return out;
	}

	private static MissionMessage mission(MessageUnpacker in) throws IOException, MalformedMessageException {
		int n = mapHeader(in, "mission");
		long seq = -1;
		double t = Double.NaN;
		String event = null;
		int taskIndex = -1;
		double[] goal = null;
		String reason = null;
		for (int i = 0; i < n; i++) {
			String key = in.unpackString();
			switch (key) {
			case "seq" -> seq = integer(in, "seq");
			case "t" -> t = real(in, "t");
			case "event" -> event = string(in, "event");
			case "task_index" -> taskIndex = (int) integer(in, "task_index");
			case "goal" -> {
				if (in.getNextFormat() == MessageFormat.NIL) {
					in.unpackNil();
				} else {
					goal = new double[3];
					reals(in, goal, "goal");
				}
			}
			case "reason" -> reason = in.getNextFormat() == MessageFormat.NIL ? nilNull(in) : string(in, "reason");
			default -> in.skipValue();
			}
		}
		require(seq >= 0, "missing-field", "mission event without seq");
		require(Double.isFinite(t), "missing-field", "mission event without a finite t");
		require(event != null && EVENTS.contains(event), "bad-field", "unknown mission event " + event);
		return new MissionMessage(seq, t, event, taskIndex, goal, reason);
	}

	private static int mapHeader(MessageUnpacker in, String what) throws IOException, MalformedMessageException {
		require(in.hasNext(), "empty", "no " + what + " map");
		require(in.getNextFormat().getValueType() == ValueType.MAP, "not-a-map", what + " is not a map");
		return in.unpackMapHeader();
	}

	private static int arrayHeader(MessageUnpacker in, String what) throws IOException, MalformedMessageException {
		require(in.getNextFormat().getValueType() == ValueType.ARRAY, "bad-field", what + " is not an array");
		return in.unpackArrayHeader();
	}

	private static String string(MessageUnpacker in, String what) throws IOException, MalformedMessageException {
		require(in.getNextFormat().getValueType() == ValueType.STRING, "bad-field", what + " is not a string");
		return in.unpackString();
	}

	private static long integer(MessageUnpacker in, String what) throws IOException, MalformedMessageException {
		require(in.getNextFormat().getValueType() == ValueType.INTEGER, "bad-field", what + " is not an integer");
		return in.unpackLong();
	}

	private static double real(MessageUnpacker in, String what) throws IOException, MalformedMessageException {
		ValueType type = in.getNextFormat().getValueType();
		if (type == ValueType.FLOAT) {
			return in.unpackDouble();
		}
		require(type == ValueType.INTEGER, "bad-field", what + " is not a number");
		return in.unpackLong();
	}

	private static void reals(MessageUnpacker in, double[] into, String what)
			throws IOException, MalformedMessageException {
		int n = arrayHeader(in, what);
		require(n == into.length, "bad-field", what + " needs " + into.length + " numbers, got " + n);
		for (int i = 0; i < n; i++) {
			into[i] = real(in, what);
			// poses, twists, odometry and goals are always finite (the protocol never sends NaN, +inf only in
			// laser values): a NaN pose would become a footprint nothing can be measured against
			require(Double.isFinite(into[i]), "bad-field", what + " with a non-finite number " + into[i]);
		}
	}

	private static double[] realArray(MessageUnpacker in, String what) throws IOException, MalformedMessageException {
		if (in.getNextFormat() == MessageFormat.NIL) {
			in.unpackNil();
			return null;
		}
		int n = arrayHeader(in, what);
		require(n <= MAX_REALS, "bad-field", what + " with " + n + " numbers");
		double[] out = new double[n];
		for (int i = 0; i < n; i++) {
			out[i] = real(in, what);
		}
		return out;
	}

	private static void require(boolean ok, String kind, String detail) throws MalformedMessageException {
		if (!ok) {
			throw new MalformedMessageException(kind, detail);
		}
	}
}
