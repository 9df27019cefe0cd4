// SPDX-License-Identifier: EPL-2.0
// What the page knows about the run, fed message by message, read once per drawn frame.
//
// Keeping up with a run 20x faster than real time: a state message only replaces `latest` (O(1), nothing
// drawn), so however many arrive between two screen refreshes, the next frame draws the newest and the others
// are counted as dropped. Signals and mission events are few and all kept. Every topic's `seq` is checked:
// a jump is a gap, shown to the user and listed in `gaps`.
import type { MissionMessage, SignalMessage, StateMessage, ViewConfig } from "./config";
import { asMission, asSignal, asState } from "./config";

export type Zone = "FAR" | "CLOSE" | "COLLISION";
export type TaskState = "PENDING" | "ACTIVE" | "SUCCEEDED" | "FAILED";
export type Topic = "state" | "mission" | "signal";

export interface Gap {
  readonly topic: Topic;
  /** First and last missing seq. */
  readonly from: number;
  readonly to: number;
  /** Simulation time of the message after the gap. */
  readonly t: number;
  readonly atMs: number;
}

export interface SignalEntry {
  readonly seq: number;
  readonly t: number;
  readonly signal: string;
  readonly object: string;
  readonly distance: number;
  readonly utility: number;
  readonly total: number;
  /** Where the robot was at `t` (true pose), or null when no state was seen yet. */
  readonly x: number | null;
  readonly y: number | null;
  readonly receivedAtMs: number;
  /** Wall time (Unix ms) its row was put into the list; null until then. */
  shownAtMs: number | null;
}

/** A fault's window on the timeline, from its mission events; `end` null while it is open. */
export interface FaultWindow {
  readonly fault: string;
  readonly begin: number;
  end: number | null;
}

export interface TaskEntry {
  readonly index: number;
  goal: readonly [number, number] | null;
  state: TaskState;
  reason: string | null;
  started: number | null;
  ended: number | null;
}

/** Unix milliseconds with sub-millisecond resolution, comparable with Python's time.time() * 1000. */
export function wallMs(): number {
  return performance.timeOrigin + performance.now();
}

const ZONE_RANK: Readonly<Record<Zone, number>> = { FAR: 0, CLOSE: 1, COLLISION: 2 };
const GEOM = /^SIG_GEOM_(FAR|CLOSE|COLLISION)_TRANSIT_(FAR|CLOSE|COLLISION)$/;
const HISTORY = 512;
const TRAIL_STEP = 0.02;

export class LiveModel {
  latest: StateMessage | null = null;
  latestAtMs = 0;
  /** A state arrived since the last frame took one. */
  fresh = false;
  statesReceived = 0;
  statesDropped = 0;
  malformed = 0;
  lastMessageAtMs = 0;

  readonly signals: SignalEntry[] = [];
  /** Signals not yet shown in the list (the list is updated once per frame). */
  readonly unshown: SignalEntry[] = [];
  total = 0;
  readonly utility: [number, number][] = [[0, 0]];
  readonly tasks: TaskEntry[];
  readonly gaps: Gap[] = [];
  readonly faults: FaultWindow[] = [];
  /** Geometric zone of the robot towards each object that is not FAR (from the monitor's signals). */
  readonly zones = new Map<string, Zone>();
  began: number | null = null;
  ended: { t: number; atMs: number; reason: string | null } | null = null;
  /** Bumped whenever signals, tasks, gaps or the end change: panels redraw only then. */
  revision = 0;

  /** The robot's true path, thinned to a point per TRAIL_STEP metres: [x0, y0, x1, y1, ...]. */
  readonly trail: number[] = [];
  private readonly history = new Float64Array(HISTORY * 3);
  private historyCount = 0;
  private readonly nextSeq: Record<Topic, number> = { state: 0, mission: 0, signal: 0 };
  private readonly seen: Record<Topic, boolean> = { state: false, mission: false, signal: false };

  constructor(private readonly config: ViewConfig) {
    this.tasks = (config.mission?.goals ?? []).map((goal) => ({
      index: goal.index, goal: [goal.x, goal.y] as const, state: "PENDING", reason: null, started: null, ended: null,
    }));
  }

  onState(payload: unknown): void {
    const message = asState(payload);
    if (message === null) {
      this.malformed += 1;
      return;
    }
    const now = wallMs();
    this.checkSeq("state", message.seq, message.t, now);
    this.statesReceived += 1;
    if (this.fresh) this.statesDropped += 1;
    this.latest = message;
    this.latestAtMs = now;
    this.lastMessageAtMs = now;
    this.fresh = true;
    const [x = 0, y = 0] = message.robot.pose;
    const slot = (this.historyCount % HISTORY) * 3;
    this.history[slot] = message.t;
    this.history[slot + 1] = x;
    this.history[slot + 2] = y;
    this.historyCount += 1;
    const n = this.trail.length;
    if (n === 0 || Math.hypot(x - (this.trail[n - 2] ?? 0), y - (this.trail[n - 1] ?? 0)) >= TRAIL_STEP) {
      this.trail.push(x, y);
    }
  }

  onSignal(payload: unknown): void {
    const message = asSignal(payload);
    if (message === null) {
      this.malformed += 1;
      return;
    }
    const now = wallMs();
    this.lastMessageAtMs = now;
    this.checkSeq("signal", message.seq, message.t, now);
    this.addSignal(message, now);
  }

  onMission(payload: unknown): void {
    const message = asMission(payload);
    if (message === null) {
      this.malformed += 1;
      return;
    }
    const now = wallMs();
    this.lastMessageAtMs = now;
    this.checkSeq("mission", message.seq, message.t, now);
    this.applyMission(message, now);
  }

  /** The newest state if it was not drawn yet; marks it drawn. */
  takeFresh(): StateMessage | null {
    if (!this.fresh) return null;
    this.fresh = false;
    return this.latest;
  }

  zone(): Zone {
    let worst: Zone = "FAR";
    for (const zone of this.zones.values()) {
      if (ZONE_RANK[zone] > ZONE_RANK[worst]) worst = zone;
    }
    return worst;
  }

  /** The robot's true position at simulation time `t` (the last state at or before it). */
  positionAt(t: number): [number, number] | null {
    const count = Math.min(this.historyCount, HISTORY);
    for (let k = 0; k < count; k += 1) {
      const slot = ((this.historyCount - 1 - k) % HISTORY) * 3;
      if ((this.history[slot] ?? Infinity) <= t + 1e-9) {
        return [this.history[slot + 1] ?? 0, this.history[slot + 2] ?? 0];
      }
    }
    if (count === 0) return null;
    const oldest = ((this.historyCount - count) % HISTORY) * 3;
    return [this.history[oldest + 1] ?? 0, this.history[oldest + 2] ?? 0];
  }

  private addSignal(message: SignalMessage, now: number): void {
    const utility = this.config.utilities[message.signal] ?? 0;
    this.total += utility;
    this.utility.push([message.t, this.total]);
    const where = this.positionAt(message.t);
    const entry: SignalEntry = {
      seq: message.seq, t: message.t, signal: message.signal, object: String(message.object ?? ""),
      distance: typeof message.distance === "number" ? message.distance : NaN, utility, total: this.total,
      x: where?.[0] ?? null, y: where?.[1] ?? null, receivedAtMs: now, shownAtMs: null,
    };
    this.signals.push(entry);
    this.unshown.push(entry);
    const geom = GEOM.exec(message.signal);
    if (geom !== null) {
      const to = geom[2] as Zone;
      if (to === "FAR") this.zones.delete(entry.object);
      else this.zones.set(entry.object, to);
    }
    if (message.signal === "SIG_MISSION_END" && this.ended === null) {
      this.ended = { t: message.t, atMs: now, reason: null };
    }
    this.revision += 1;
  }

  private applyMission(message: MissionMessage, now: number): void {
    if (message.event === "BEGIN") this.began = message.t;
    const edge = this.config.faults?.[message.event];
    if (edge !== undefined) {
      if (edge.begin) {
        this.faults.push({ fault: edge.fault, begin: message.t, end: null });
      } else {
        // a fault's windows never overlap (one pulse ends before the next begins): the open one is the last
        for (let i = this.faults.length - 1; i >= 0; i -= 1) {
          const open = this.faults[i];
          if (open !== undefined && open.fault === edge.fault && open.end === null) {
            open.end = message.t;
            break;
          }
        }
      }
    }
    if (message.event === "END") {
      this.ended = { t: message.t, atMs: now, reason: message.reason ?? this.ended?.reason ?? null };
    }
    const task = this.tasks.find((candidate) => candidate.index === message.task_index);
    if (message.task_index >= 0) {
      const entry = task ?? this.newTask(message.task_index);
      const goal = message.goal;
      if (goal !== null && goal.length >= 2) entry.goal = [goal[0] ?? 0, goal[1] ?? 0];
      if (message.event === "TASK_START") {
        entry.state = "ACTIVE";
        entry.started = message.t;
      } else if (message.event === "TASK_SUCCESS" || message.event === "TASK_FAIL") {
        entry.state = message.event === "TASK_SUCCESS" ? "SUCCEEDED" : "FAILED";
        entry.ended = message.t;
        entry.reason = message.reason ?? null;
      }
    }
    this.revision += 1;
  }

  private newTask(index: number): TaskEntry {
    const task: TaskEntry = { index, goal: null, state: "PENDING", reason: null, started: null, ended: null };
    this.tasks.push(task);
    this.tasks.sort((a, b) => a.index - b.index);
    return task;
  }

  private checkSeq(topic: Topic, seq: number, t: number, now: number): void {
    // A page that joins late starts at whatever it gets first: only later jumps are gaps.
    if (this.seen[topic] && seq > this.nextSeq[topic]) {
      this.gaps.push({ topic, from: this.nextSeq[topic], to: seq - 1, t, atMs: now });
      this.revision += 1;
    }
    this.seen[topic] = true;
    this.nextSeq[topic] = Math.max(this.nextSeq[topic], seq + 1);
  }
}
