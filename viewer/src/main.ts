// SPDX-License-Identifier: EPL-2.0
// The live view: loads /config.json, subscribes to the run's topics and draws at screen rate.
//
// Messages only update the model; one requestAnimationFrame loop draws the newest state, so a run 20x faster
// than real time costs one draw per screen refresh however many states arrive (the rest are dropped, counted).
// `window.reiView` exposes what was drawn, for tests and for curious people in the console.
import "./style.css";
import type { ViewConfig } from "./config";
import { loadConfig } from "./config";
import { UtilityChart } from "./draw/chart";
import type { DrawnRobot } from "./draw/scene";
import { MapView } from "./draw/scene";
import { contains } from "./geometry";
import type { FaultWindow, Gap, SignalEntry, TaskEntry } from "./model";
import { LiveModel, wallMs } from "./model";
import type { Condition } from "./panels";
import { Panels } from "./panels";
import type { FrameSummary } from "./stats";
import { FrameStats } from "./stats";
import type { LinkStatus } from "./wamp";
import { connect } from "./wamp";

/** The page's state as last drawn (`window.reiView.state`). */
export interface ViewState {
  condition: Condition;
  link: LinkStatus;
  subscribed: boolean;
  /** The robot as the last frame drew it, and when (Unix ms). */
  robot: DrawnRobot | null;
  drawnAtMs: number;
  /** Last frame's delay between the drawn state's arrival and its drawing. */
  lagMs: number;
  received: { state: number; signal: number; mission: number };
  dropped: number;
  malformed: number;
  movers: number;
  gaps: readonly Gap[];
  faults: readonly FaultWindow[];
  signals: readonly SignalEntry[];
  total: number;
  tasks: readonly TaskEntry[];
  ended: { t: number; atMs: number; reason: string | null } | null;
  transform: { scale: number; ox: number; oy: number };
}

export interface ReiView {
  readonly config: ViewConfig;
  readonly state: ViewState;
  frames(): FrameSummary;
  resetFrames(): void;
}

declare global {
  interface Window {
    reiView?: ReiView;
  }
}

function box(id: string): HTMLElement {
  const found = document.getElementById(id);
  if (found === null) throw new Error(`page element #${id} is missing`);
  return found;
}

function start(config: ViewConfig): void {
  const model = new LiveModel(config);
  const mapCanvas = box("map") as HTMLCanvasElement;
  const map = new MapView(mapCanvas, config, model);
  const chart = new UtilityChart(box("utility") as HTMLCanvasElement);
  const panels = new Panels(config, model);
  const stats = new FrameStats();
  let received = { signal: 0, mission: 0 };
  const state: ViewState = {
    condition: "connecting", link: "connecting", subscribed: false, robot: null, drawnAtMs: 0, lagMs: 0,
    received: { state: 0, signal: 0, mission: 0 }, dropped: 0, malformed: 0, movers: 0, gaps: model.gaps,
    faults: model.faults, signals: model.signals, total: 0, tasks: model.tasks, ended: null, transform: { scale: 1, ox: 0, oy: 0 },
  };
  window.reiView = { config, state, frames: () => stats.summary(), resetFrames: () => stats.reset() };

  connect(config, {
    state: (payload) => model.onState(payload),
    signal: (payload) => {
      received = { ...received, signal: received.signal + 1 };
      model.onSignal(payload);
    },
    mission: (payload) => {
      received = { ...received, mission: received.mission + 1 };
      model.onMission(payload);
    },
    link: (status, detail) => {
      panels.link = status;
      panels.linkDetail = detail;
      state.link = status;
    },
    subscribed: () => {
      panels.subscribed = true;
      state.subscribed = true;
      if (config.hello !== null) void fetch(config.hello, { method: "POST" }).catch(() => undefined);
    },
    retry: () => model.ended === null,
  });

  const mapBox = box("map-box");
  const chartCanvas = box("utility");
  let mapSize = { width: mapBox.clientWidth, height: mapBox.clientHeight };
  let chartSize = { width: chartCanvas.clientWidth, height: chartCanvas.clientHeight };
  let sized = true;
  new ResizeObserver(() => {
    mapSize = { width: mapBox.clientWidth, height: mapBox.clientHeight };
    chartSize = { width: chartCanvas.clientWidth, height: chartCanvas.clientHeight };
    sized = true;
  }).observe(mapBox);

  let drawnRevision = -1;
  let chartDrawnAt = 0;
  let perfText = "";
  let perfAt = 0;
  const frame = (): void => {
    const begin = performance.now();
    const ratio = window.devicePixelRatio || 1;
    let changed = false;
    if (sized) {
      sized = false;
      map.resize(mapSize.width, mapSize.height, ratio);
      chart.resize(chartSize.width, chartSize.height, ratio);
      changed = true;
      drawnRevision = -1;
    }
    const fresh = model.takeFresh();
    if (fresh !== null || changed || model.revision !== drawnRevision) {
      const robot = map.draw(fresh);
      const now = wallMs();
      state.robot = robot;
      state.drawnAtMs = now;
      state.lagMs = now - model.latestAtMs;
      state.movers = map.moverCount;
      state.transform = { scale: map.transform.scale, ox: map.transform.ox, oy: map.transform.oy };
      changed = true;
    }
    const now = wallMs();
    if (model.revision !== drawnRevision || (fresh !== null && now - chartDrawnAt > 500)) {
      chart.draw(model.utility, model.latest?.t ?? 0, model.gaps, model.faults);
      chartDrawnAt = now;
      drawnRevision = model.revision;
    }
    if (now - perfAt > 500) {
      const summary = stats.summary();
      perfText = `frame ${summary.meanMs.toFixed(1)} ms (p95 ${summary.p95Ms.toFixed(1)}) · ` +
        `dropped ${model.statesDropped} · lag ${state.lagMs.toFixed(0)} ms`;
      perfAt = now;
    }
    state.condition = panels.update(now, perfText);
    state.received = { state: model.statesReceived, ...received };
    state.dropped = model.statesDropped;
    state.malformed = model.malformed;
    state.total = model.total;
    state.ended = model.ended;
    if (changed) stats.record(performance.now() - begin, begin);
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
  installTooltip(mapCanvas, config, map);
}

/** Names on hover: moving objects first, then walls and furniture, then floors. */
function installTooltip(canvas: HTMLCanvasElement, config: ViewConfig, map: MapView): void {
  const tip = box("tooltip");
  const bodies = [...(config.world?.objects ?? [])].sort(
    (a, b) => Number(a.category === "FLOOR") - Number(b.category === "FLOOR"));
  canvas.addEventListener("mousemove", (event) => {
    const [x, y] = map.transform.toWorld(event.offsetX, event.offsetY);
    const mover = map.moverAt(x, y);
    const body = mover === null ? bodies.find((candidate) => contains(candidate, x, y)) : undefined;
    const text = mover !== null ? mover
      : body === undefined ? null
        : body.category === "FLOOR" ? `floor ${body.name}` : `${body.name} (${body.type})`;
    if (text === null) {
      tip.hidden = true;
      return;
    }
    tip.textContent = `${text} · (${x.toFixed(2)}, ${y.toFixed(2)})`;
    tip.style.left = `${event.offsetX + 12}px`;
    tip.style.top = `${event.offsetY + 12}px`;
    tip.hidden = false;
  });
  canvas.addEventListener("mouseleave", () => {
    tip.hidden = true;
  });
}

loadConfig().then(start, (error: unknown) => {
  const status = box("status");
  status.textContent = `cannot start: ${String(error)}`;
  status.className = "status disconnected";
});
