// SPDX-License-Identifier: EPL-2.0
// The HTML around the map: status bar, banners (gap, stall, end), the mission's tasks and the signal list.
// Updated at most once per frame, and the lists only when the model's revision changed.
import type { ViewConfig } from "./config";
import { byId } from "./dom";
import { signalColour, ZONE } from "./draw/colours";
import type { LiveModel, SignalEntry } from "./model";
import { wallMs } from "./model";
import type { LinkStatus } from "./wamp";

/** Rows kept in the list; older signals stay in the model (and the counts), not in the page. */
const MAX_ROWS = 400;
/** A gap stays in the banner this long after it was noticed. */
const GAP_BANNER_MS = 8000;
/** No state for this long while the run goes on: the stream stalled. */
export const STALL_MS = 1500;

function signed(value: number): string {
  return `${value > 0 ? "+" : ""}${Number.isInteger(value) ? value : value.toFixed(1)}`;
}

export type Condition = "connecting" | "waiting" | "live" | "stalled" | "ended" | "disconnected";

export class Panels {
  private readonly status = byId("status");
  private readonly clock = byId("clock");
  private readonly zone = byId("zone");
  private readonly total = byId("total");
  private readonly perf = byId("perf");
  private readonly banners = byId("banners");
  private readonly tasks = byId<HTMLOListElement>("tasks");
  private readonly list = byId<HTMLOListElement>("signal-list");
  private readonly count = byId("signal-count");
  private shownRevision = -1;
  private bannerKey = "";
  link: LinkStatus = "connecting";
  linkDetail = "";
  subscribed = false;

  constructor(private readonly config: ViewConfig, private readonly model: LiveModel) {
    byId("run").textContent = `run ${config.run_id}`;
    byId("mission-name").textContent = config.mission?.name ?? "";
  }

  /** What the stream is doing now, as one word (also exposed to tests). */
  condition(now: number): Condition {
    if (this.model.ended !== null) return "ended";
    if (this.link === "closed" || this.link === "retrying") return "disconnected";
    if (this.link === "connecting" || !this.subscribed) return "connecting";
    if (this.model.statesReceived === 0) return "waiting";
    return now - this.model.latestAtMs > STALL_MS ? "stalled" : "live";
  }

  update(now: number, perf: string): Condition {
    const model = this.model;
    const condition = this.condition(now);
    const latest = model.latest;
    this.setText(this.status, this.statusText(condition, now));
    this.status.className = `status ${condition}`;
    this.setText(this.clock, latest === null ? "t = –" : `t = ${latest.t.toFixed(2)} s`);
    const zone = model.zone();
    this.setText(this.zone, `zone ${zone}`);
    this.zone.style.background = ZONE[zone];
    this.setText(this.total, `utility ${signed(model.total)}`);
    this.setText(this.perf, perf);
    this.updateBanners(condition, now);
    if (model.unshown.length > 0) this.appendSignals(model.unshown.splice(0));
    if (model.revision !== this.shownRevision) {
      this.shownRevision = model.revision;
      this.renderTasks();
    }
    return condition;
  }

  private statusText(condition: Condition, now: number): string {
    switch (condition) {
      case "connecting": return `connecting to ${this.config.router.url}…`;
      case "waiting": return "connected, waiting for the run…";
      case "live": return "live";
      case "stalled": return `no data for ${((now - this.model.latestAtMs) / 1000).toFixed(1)} s`;
      case "ended": return "run ended";
      case "disconnected": return `disconnected: ${this.linkDetail}`;
    }
  }

  private updateBanners(condition: Condition, now: number): void {
    const lines: [string, string][] = [];
    const ended = this.model.ended;
    if (ended !== null) {
      const why = ended.reason !== null ? ` (${ended.reason})` : "";
      lines.push(["ended", `Run ended at t = ${ended.t.toFixed(1)} s${why} — total utility ${signed(this.model.total)}`]);
    }
    const recent = this.model.gaps.filter((gap) => now - gap.atMs < GAP_BANNER_MS);
    for (const gap of recent.slice(-3)) {
      const count = gap.to - gap.from + 1;
      lines.push(["gap", `Stream gap: ${count} ${gap.topic} message${count === 1 ? "" : "s"} lost ` +
        `(seq ${gap.from}–${gap.to}) before t = ${gap.t.toFixed(2)} s`]);
    }
    if (condition === "stalled") {
      lines.push(["stalled", `No state message for ${((now - this.model.latestAtMs) / 1000).toFixed(0)} s — ` +
        "the simulation paused, stopped or the router is overloaded"]);
    }
    if (condition === "disconnected") lines.push(["disconnected", `Disconnected from the router: ${this.linkDetail}`]);
    const key = lines.map(([kind, text]) => kind + text).join("|");
    if (key === this.bannerKey) return;
    this.bannerKey = key;
    this.banners.replaceChildren(...lines.map(([kind, text]) => {
      const div = document.createElement("div");
      div.className = `banner ${kind}`;
      div.textContent = text;
      return div;
    }));
  }

  private appendSignals(entries: readonly SignalEntry[]): void {
    const fragment = document.createDocumentFragment();
    for (const entry of entries) {
      const row = document.createElement("li");
      row.dataset["seq"] = String(entry.seq);
      row.dataset["signal"] = entry.signal;
      const chip = document.createElement("span");
      chip.className = "chip";
      chip.style.background = signalColour(this.config.colours, entry.signal);
      // Mission signals carry a distance too, but only the geometric and laser ones mean one.
      const spatial = !entry.signal.startsWith("SIG_MISSION");
      const distance = spatial && Number.isFinite(entry.distance) ? ` ${entry.distance.toFixed(3)} m` : "";
      row.append(chip, `${entry.t.toFixed(2)} s  ${entry.signal.replace(/^SIG_/, "")}  ${entry.object}${distance}`);
      const utility = document.createElement("span");
      utility.className = `utility ${entry.utility < 0 ? "negative" : entry.utility > 0 ? "positive" : ""}`;
      utility.textContent = `${signed(entry.utility)} → ${signed(entry.total)}`;
      row.append(utility);
      fragment.prepend(row);
    }
    this.list.prepend(fragment);
    while (this.list.childElementCount > MAX_ROWS) this.list.lastElementChild?.remove();
    const shownAt = wallMs();
    for (const entry of entries) entry.shownAtMs = shownAt;
    this.count.textContent = String(this.model.signals.length);
  }

  private renderTasks(): void {
    const rows = this.model.tasks.map((task) => {
      const row = document.createElement("li");
      row.className = `task ${task.state.toLowerCase()}`;
      row.dataset["state"] = task.state;
      const goal = task.goal !== null ? ` (${task.goal[0].toFixed(2)}, ${task.goal[1].toFixed(2)})` : "";
      const when = task.ended !== null ? ` at ${task.ended.toFixed(1)} s` : task.started !== null
        ? ` since ${task.started.toFixed(1)} s` : "";
      row.textContent = `goal ${task.index}${goal}: ${task.state}${when}${task.reason !== null ? ` — ${task.reason}` : ""}`;
      return row;
    });
    this.tasks.replaceChildren(...rows);
  }

  private setText(target: HTMLElement, text: string): void {
    if (target.textContent !== text) target.textContent = text;
  }
}
