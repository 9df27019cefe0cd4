/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.monitor.pipeline;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;

import org.locationtech.jts.geom.Envelope;
import org.rei.monitor.config.MonitorSpec;
import org.rei.monitor.config.World;
import org.rei.monitor.engine.DrlSources;
import org.rei.monitor.engine.MonitorEngine;
import org.rei.monitor.engine.SessionFactory;
import org.rei.monitor.engine.Thresholds;
import org.rei.monitor.geometry.Footprint;
import org.rei.monitor.geometry.FootprintDistance;
import org.rei.monitor.geometry.ObstacleIndex;
import org.rei.monitor.geometry.Shape;
import org.rei.monitor.model.RuntimeModelUpdater;
import org.rei.monitor.model.Snapshots;
import org.rei.monitor.signals.SignalPublisher;
import org.rei.monitor.wire.MalformedMessageException;
import org.rei.monitor.wire.MissionMessage;
import org.rei.monitor.wire.ObjectState;
import org.rei.monitor.wire.RobotState;
import org.rei.monitor.wire.StateMessage;
import org.rei.monitor.wire.StaticEntryCache;
import org.rei.monitor.wire.WireDecoder;
import org.rei.vepl.runtime.MissionEvent;
import org.rei.vepl.runtime.QueryEvent;

/**
 * The whole monitor pipeline for one run, the same for live and replay: decode, check order, update the EMF
 * runtime model, place footprints, measure the robot's neighbourhood, update the facts, run queries and
 * transition rules, publish signals. Not thread-safe: one thread feeds it (the live client serialises).
 */
public final class Monitor implements AutoCloseable {

	/** Signal reporting lost messages: object is the topic, distance the number of messages missing. */
	public static final String DATA_GAP = "SIG_MONITOR_DATA_GAP";

	private final String robotName;
	private final Shape robotShape;
	private final double prefilter;
	private final double epsCollision;
	private final ObstacleIndex index = new ObstacleIndex();
	private final java.util.Map<String, Shape> shapes = new java.util.HashMap<>();
	private final java.util.Map<String, String> categories = new java.util.HashMap<>();
	private final RuntimeModelUpdater model;
	private final MonitorEngine engine;
	private final SignalPublisher signals;
	private final InputGuard guard;
	private final InputGuard.Sequence stateSeq = new InputGuard.Sequence();
	private final InputGuard.Sequence missionSeq = new InputGuard.Sequence();
	private final Set<String> touching = new HashSet<>();
	private final StaticEntryCache statics;
	private long states;
	private long missions;
	private Footprint robotFootprint;
	private final List<String> movingObstacles = new ArrayList<>();
	/** Moving obstacles the collector does not publish, with their last footprint, until one appears again. */
	private final Map<String, Footprint> unobserved = new HashMap<>();

	/**
	 * @param queryEventLog receives every query event (tests), or null
	 */
	public Monitor(String runId, World world, MonitorSpec spec, List<DrlSources.Source> rules, SignalPublisher signals,
			Consumer<String> log, List<QueryEvent> queryEventLog) {
		this.robotName = world.robot().name();
		this.robotShape = world.robot().footprint() != null ? world.robot().footprint()
				: shape(world.robot().shape(), world.robot().size());
		// the thesis's radius pre-filter: only obstacles within this distance of the footprint become facts; wider
		// than eps_close so the obstacle that just left the close zone is still known when the robot turns FAR
		this.prefilter = Math.max(2 * spec.epsClose(), 0.5);
		this.epsCollision = spec.epsCollision();
		this.signals = signals;
		this.guard = new InputGuard(log);
		this.model = RuntimeModelUpdater.create(runId, world, spec);
		this.statics = new StaticEntryCache(
				world.objects().stream().filter(o -> o.isObstacle() && !o.moves()).map(World.WorldObject::name).toList());
		for (World.WorldObject o : world.objects()) {
			if (!o.isObstacle()) {
				continue;
			}
			Shape s = o.footprint() != null ? o.footprint() : shape(o.shape(), o.size());
			shapes.put(o.name(), s);
			categories.put(o.name(), o.category());
			Footprint f = Footprint.place(o.name(), s, o.pose()[0], o.pose()[1], o.pose()[3]);
			if (o.moves()) {
				index.putMoving(f);
				movingObstacles.add(o.name());
			} else {
				index.putStatic(f);
			}
		}
		this.engine = new MonitorEngine(SessionFactory.build(rules), new Thresholds(spec.epsClose(), spec.epsCollision()),
				robotName, signals, model.model(), queryEventLog);
	}

	/** Footprint per catalogue shape: cylinders are circles, boxes and meshes (bounding box) rectangles. */
	static Shape shape(String shape, double[] size) {
		return "CYLINDER".equals(shape) ? Shape.circle(Math.max(size[0], size[1])) : Shape.rectangle(size[0], size[1]);
	}

	/** One state message as it came off the wire. Never throws for bad input. */
	public void onStateBytes(byte[] data, int offset, int length) {
		StateMessage m = decodeState(data, offset, length);
		if (m != null) {
			onState(m);
		}
	}

	/**
	 * Decodes a state message for {@link #onState}, skipping the full frame's static obstacles whose entries are
	 * byte-identical to the last ones applied (they cannot change anything); null, counted, for bad input. Apply
	 * the result before decoding the next message.
	 */
	public StateMessage decodeState(byte[] data, int offset, int length) {
		try {
			return WireDecoder.decodeState(data, offset, length, statics);
		} catch (MalformedMessageException e) {
			guard.problem(e.kind(), e.getMessage());
			return null;
		}
	}

	/** One mission message as it came off the wire. Never throws for bad input. */
	public void onMissionBytes(byte[] data, int offset, int length) {
		MissionMessage m;
		try {
			m = WireDecoder.decodeMission(data, offset, length);
		} catch (MalformedMessageException e) {
			guard.problem(e.kind(), e.getMessage());
			return;
		}
		onMission(m);
	}

	/** One decoded state message. */
	public void onState(StateMessage m) {
		if (!inOrder("state", stateSeq, m.seq(), m.t(), true)) {
			return;
		}
		if (!robotName.equals(m.robot().name())) {
			guard.problem("unknown-robot", "state of robot " + m.robot().name() + ", monitoring " + robotName);
			return;
		}
		try {
			step(m);
			statics.applied(m);
			states++;
		} catch (RuntimeException e) {
			statics.failed(m);
			guard.problem("failed-state", e.toString());
		}
	}

	// state times increase strictly (one snapshot per step); mission events of one step share their time
	private boolean inOrder(String topic, InputGuard.Sequence seq, long n, double t, boolean strict) {
		long missing = seq.missingBefore(n);
		if (missing < 0 || (strict ? !(t > seq.lastT()) : t < seq.lastT())) {
			guard.problem("out-of-order-" + topic, "seq " + n + " at t " + t + " after t " + seq.lastT());
			return false;
		}
		if (missing > 0) {
			guard.problem("gap-" + topic, missing + " message(s) missing before seq " + n);
			signals.emit(DATA_GAP, t, robotName, topic, missing);
		}
		seq.accept(n, t);
		return true;
	}

	private void step(StateMessage m) {
		model.applyState(m);
		if (m.full()) {
			parkUnobserved(m);
		}
		for (ObjectState o : m.objects()) {
			Footprint old = index.get(o.name());
			Footprint parked = old == null ? unobserved.remove(o.name()) : null;
			if (parked != null) {
				index.putMoving(Footprint.place(o.name(), parked.shape(), o.x(), o.y(), o.yaw()));
			} else if (old == null) {
				guard.problem("unknown-object", "object " + o.name() + " is not in world.json (no footprint)");
			} else if (!old.isAt(o.x(), o.y(), o.yaw())) {
				Footprint f = Footprint.place(o.name(), old.shape(), o.x(), o.y(), o.yaw());
				if (index.isStatic(o.name()) && !"HUMAN".equals(o.category()) && !"DYNAMIC".equals(o.category())) {
					index.putStatic(f);
				} else {
					index.putMoving(f);
				}
			}
		}
		touching.clear();
		if (m.contacts() != null) {
			for (String[] pair : m.contacts()) {
				String other = robotName.equals(pair[0]) ? pair[1] : robotName.equals(pair[1]) ? pair[0] : null;
				if (other != null && index.get(other) != null) {
					touching.add(other);
				}
			}
		}
		var r = m.robot();
		robotFootprint = Footprint.place(robotName, robotShape, r.x(), r.y(), r.yaw());
		engine.beginStep(m.t());
		Envelope area = new Envelope(robotFootprint.envelope());
		area.expandBy(prefilter);
		String[] nearest = { "" };
		double[] best = { Double.POSITIVE_INFINITY };
		boolean[] bestCollides = { false };
		index.candidates(area, f -> {
			double d = FootprintDistance.between(robotFootprint, f);
			boolean contact = touching.contains(f.name());
			if (d >= prefilter && !contact) {
				return;
			}
			engine.proximity(f.name(), categories.get(f.name()), d, contact);
			boolean collides = contact || d < epsCollision;
			if (collides && !bestCollides[0] || collides == bestCollides[0] && d < best[0]) {
				nearest[0] = f.name();
				best[0] = d;
				bestCollides[0] = collides;
			}
		});
		for (String name : touching) {
			Footprint f = index.get(name);
			if (!f.envelope().intersects(area)) { // a contact the geometry does not see still counts
				double d = FootprintDistance.between(robotFootprint, f);
				engine.proximity(name, categories.get(name), d, true);
				if (!bestCollides[0] || d < best[0]) {
					nearest[0] = name;
					best[0] = d;
					bestCollides[0] = true;
				}
			}
		}
		if (r.hasLaser()) {
			double gap = laserGap(r);
			model.applyLaserClearance(gap);
			engine.laser(gap);
		}
		engine.endStep(nearest[0], best[0]);
	}

	/**
	 * A full frame lists every object the collector observes (docs/protocol.md): a moving obstacle of world.json
	 * that it leaves out is not published (the collector's {@code objects} setting), so its last known place says
	 * nothing; it is not judged until a message brings it again.
	 */
	private void parkUnobserved(StateMessage m) {
		Set<String> present = new HashSet<>();
		for (ObjectState o : m.objects()) {
			present.add(o.name());
		}
		for (String name : movingObstacles) {
			if (!present.contains(name)) {
				Footprint f = index.removeMoving(name);
				if (f != null) {
					unobserved.put(name, f);
				}
			}
		}
	}

	/**
	 * The laser's distance to the footprint, comparable with the geometry's gaps: the collector's per-beam
	 * clearance; a producer that sends only the minimum range gets the sensor at the centre less the inscribed
	 * radius, which under-reads nothing but over-reads towards the corners.
	 */
	private double laserGap(RobotState r) {
		if (!Double.isNaN(r.laserClearance())) {
			return r.laserClearance();
		}
		return Math.max(0, r.laserMin() - robotShape.inscribedRadius());
	}

	/** One decoded mission message. */
	public void onMission(MissionMessage m) {
		if (!inOrder("mission", missionSeq, m.seq(), m.t(), false)) {
			return;
		}
		try {
			model.applyMission(m);
			double range = 0;
			if (m.goal() != null && robotFootprint != null) {
				range = Math.hypot(m.goal()[0] - robotFootprint.x(), m.goal()[1] - robotFootprint.y());
			}
			engine.mission(new MissionEvent(m.event(), m.taskIndex(), robotName, range, m.t()));
			missions++;
		} catch (RuntimeException e) {
			guard.problem("failed-mission", e.toString());
		}
	}

	/** The runtime model as XMI now. */
	public String snapshot() {
		return Snapshots.toXmi(model.resource());
	}

	public RuntimeModelUpdater model() {
		return model;
	}

	public SignalPublisher signals() {
		return signals;
	}

	public InputGuard guard() {
		return guard;
	}

	public MonitorEngine engine() {
		return engine;
	}

	public long statesProcessed() {
		return states;
	}

	public long missionsProcessed() {
		return missions;
	}

	/** Full-frame entries of unchanged static obstacles skipped without decoding. */
	public long staticEntriesSkipped() {
		return statics.skipped();
	}

	@Override
	public void close() {
		engine.close();
	}
}
