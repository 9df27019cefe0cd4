// SPDX-License-Identifier: EPL-2.0
// The HTML around the diagram: the palette, the selection (with a trajectory's points), the mission and its
// goals, the monitor's thresholds and the issues. Rebuilt from the State on every change; lists are short,
// except issues, which are capped so a room full of errors does not build thousands of rows.
import { byId } from "../dom";
import { HUMAN } from "../draw/colours";
import { formatSeconds } from "./draw/items";
import type { CrowdDraft, Selection, Tool } from "./model";
import type { RoomIndex } from "./room";
import type { Issue, Mover, PaletteType, PointSpec, State, StopSpec } from "./types";

const MAX_ISSUE_ROWS = 300;

/** What the panels ask the editor to do. */
export interface Actions {
  choosePalette(type: PaletteType): void;
  select(selection: Selection | null): void;
  showIssue(issue: Issue): void;
  setYaw(degrees: number): void;
  moveGoal(from: number, to: number): void;
  removeGoal(index: number): void;
  /** Changes the points of the draft, or of the selected mover at once when no draft is open. */
  editPoints(points: PointSpec[], loop: boolean): void;
  /** Draws a new path for the selected mover, or extends its current one. */
  startPath(extend?: boolean): void;
  finishPath(): void;
  cancelPath(): void;
  /** Changes the stops of the route being drawn, or of the selected person's route at once. */
  editStops(stops: StopSpec[], loop: boolean): void;
  /** Places a new crowd, or changes the selected crowd's areas (`existing`). */
  startCrowd(existing?: boolean): void;
  /** Changes the crowd being placed, or the selected crowd's size or rate at once. */
  editCrowd(change: Partial<CrowdDraft>): void;
}

interface Props {
  class?: string;
  text?: string;
  title?: string;
}

function el<K extends keyof HTMLElementTagNameMap>(tag: K, props: Props = {},
                                                   parent?: Element): HTMLElementTagNameMap[K] {
  const element = document.createElement(tag);
  if (props.class !== undefined) element.className = props.class;
  if (props.text !== undefined) element.textContent = props.text;
  if (props.title !== undefined) element.title = props.title;
  if (parent !== undefined) parent.appendChild(element);
  return element;
}

function button(text: string, title: string, parent: Element, onClick: () => void, className = ""): HTMLButtonElement {
  const b = el("button", { text, title, class: className }, parent);
  b.type = "button";
  b.addEventListener("click", onClick);
  return b;
}

/** A number field whose committed value, when it is a finite number, goes to ``onValue`` (blank or junk: ignored). */
function numberField(parent: Element, value: string, step: string, onValue: (value: number) => void,
                     props: Props = {}): HTMLInputElement {
  const input = el("input", props, parent);
  input.type = "number";
  input.step = step;
  input.value = value;
  input.addEventListener("change", () => {
    const parsed = Number(input.value);
    if (input.value.trim() !== "" && Number.isFinite(parsed)) onValue(parsed);
  });
  return input;
}

const metres = (value: number): string => `${Math.round(value * 1000) / 1000} m`;

export class Panels {
  private readonly palette = byId("palette");
  private readonly selection = byId("selection");
  private readonly missionHead = byId("mission");
  private readonly goals = byId<HTMLOListElement>("goals");
  private readonly monitor = byId("monitor");
  private readonly issues = byId<HTMLOListElement>("issues");
  private readonly issueCount = byId("issue-count");

  constructor(private readonly actions: Actions) {}

  render(state: State, index: RoomIndex, selection: Selection | null, tool: Tool): void {
    this.renderPalette(state.palette, tool);
    this.renderSelection(index, selection, tool);
    this.renderMission(index, selection, state.issues);
    this.renderMonitor(index, state.issues);
    this.renderIssues(state.issues);
  }

  /**
   * Furniture places an object, a human or moving type starts a new human's or moving object's path; robots,
   * floors and walls are not placed.
   */
  private renderPalette(types: readonly PaletteType[], tool: Tool): void {
    this.palette.replaceChildren();
    const list = [...types];
    if (!list.some((t) => t.category === "human" && t.name === "Human")) {
      list.push({ name: "Human", category: "human", shape: "cylinder", sizeX: 0.5, sizeY: 0.5, colour: null });
    }
    const groups: [string, PaletteType["category"], string][] = [
      ["Furniture", "object", "choose, then click a floor to place it"],
      ["Humans", "human", "choose, then click floors for the path; Finish (Enter) adds the human"],
      ["Moving objects", "dynamic", "choose, then click floors for the path; Finish (Enter) adds the moving object"],
    ];
    const chosen = tool.kind === "place" ? tool.type.name
      : tool.kind === "path" && tool.draft.isNew ? tool.draft.type ?? "Human" : null;
    for (const [title, category, hint] of groups) {
      const members = list.filter((t) => t.category === category);
      if (members.length === 0) continue;
      el("h3", { text: title, title: hint }, this.palette);
      for (const type of members) {
        const entry = button("", `${type.name} (${type.shape} ${type.sizeX} × ${type.sizeY} m): ${hint}`, this.palette,
          () => this.actions.choosePalette(type), "palette-entry");
        entry.dataset.type = type.name;
        entry.dataset.category = type.category;
        entry.classList.toggle("active", type.name === chosen);
        const swatch = el("span", { class: `swatch ${type.shape}` }, entry);
        // humans are drawn in the live view's human colour, whatever their type's
        swatch.style.background = category === "human" ? HUMAN : type.colour ?? "#9a9a9a";
        el("span", { text: type.name }, entry);
      }
    }
    el("h3", { text: "Crowds", title: "people who walk from one area of floors to another" }, this.palette);
    const crowd = button("", "A crowd: choose its from and to areas (click floors or drag a rectangle), its size and "
      + "rate; Finish (Enter) adds it", this.palette, () => this.actions.startCrowd(), "palette-entry");
    crowd.id = "new-crowd";
    crowd.classList.toggle("active", tool.kind === "crowd" && tool.draft.isNew);
    el("span", { class: "swatch crowd" }, crowd);
    el("span", { text: "Crowd" }, crowd);
  }

  private renderSelection(index: RoomIndex, selection: Selection | null, tool: Tool): void {
    const box = this.selection;
    box.replaceChildren();
    const d = index.diagram;
    if (tool.kind === "route") {
      el("p", { text: `Route of ${tool.draft.name}`, class: "title" }, box);
      el("p", { class: "hint", text: "Click floors to add stops; set a stop's wait here. Finish (Enter) saves the "
        + "route, Escape cancels." }, box);
      this.renderStops(box, tool.draft.stops, tool.draft.loop, true);
      this.draftButtons(box, tool.draft.stops.length === 0, () => this.actions.editStops([], tool.draft.loop));
      return;
    }
    if (tool.kind === "crowd") {
      this.renderCrowdDraft(box, tool.draft);
      return;
    }
    const draft = tool.kind === "path" ? tool.draft : null;
    if (draft !== null) {
      const what = draft.kind === "dynamic" ? "moving object" : "human";
      el("p", { text: draft.isNew ? `New ${what} ${draft.name}${draft.type === null ? "" : ` : ${draft.type}`}`
        : `Path of ${draft.name}`, class: "title" }, box);
      el("p", { class: "hint", text: draft.isNew || draft.points.length > 0
        ? "Click floors to add points; Finish (Enter) saves the path, Escape cancels."
        : "Click floors for the new path's points (the old path goes on Finish); Escape cancels." }, box);
      this.renderPoints(box, draft.points, draft.loop, true);
      const row = el("div", { class: "row" }, box);
      button("Finish", "save the path (Enter)", row, () => this.actions.finishPath());
      button("Cancel", "drop the drawn path (Escape)", row, () => this.actions.cancelPath());
      // a path is drawn from the mover's current points; this starts it afresh
      button("Clear", "remove every point and start the path again", row,
        () => this.actions.editPoints([], draft.loop), "clear-points").disabled = draft.points.length === 0;
      return;
    }
    if (selection === null) {
      el("p", { class: "hint", text: "Click an element to select it; drag furniture or the robot to another floor." },
        box);
      return;
    }
    const facts = el("dl", {}, box);
    const fact = (term: string, value: string): void => {
      el("dt", { text: term }, facts);
      el("dd", { text: value }, facts);
    };
    fact(selection.kind,
      selection.kind === "goal" ? `goal ${goalNumber(index, Number(selection.name))}` : selection.name);
    if (selection.kind === "object" || selection.kind === "robot") {
      const item = selection.kind === "robot" ? d.robot : d.objects.find((o) => o.name === selection.name);
      if (item === undefined || item === null) return;
      fact("type", item.footprint?.type ?? "?");
      fact("floor", item.floor ?? "?");
      const yaw = el("dd", {}, facts);
      facts.insertBefore(el("dt", { text: "yaw" }), yaw);
      numberField(yaw, String(item.yaw), "15", (value) => this.actions.setYaw(value)).id = "yaw";
      el("span", { text: " °" }, yaw);
    } else if (selection.kind === "crowd") {
      const crowd = d.crowds?.find((c) => c.name === selection.name);
      if (crowd === undefined) return;
      fact("type", crowd.footprint?.type ?? "Human");
      this.crowdFields(facts, crowd.count, crowd.rate);
      fact("from", crowd.from.map((a) => a.floor ?? "?").join(", "));
      fact("to", crowd.to.map((a) => a.floor ?? "?").join(", "));
      fact("walks", `${formatSeconds(crowd.speed)} m/s, ${crowd.behaviour}${crowd.loop ? ", loop" : ""}`);
      const row = el("div", { class: "row" }, box);
      button("Change areas", "choose the from and to floors again: click floors or drag a rectangle", row,
        () => this.actions.startCrowd(true)).id = "edit-areas";
    } else if (selection.kind === "group") {
      const group = d.groups?.find((g) => g.name === selection.name);
      if (group === undefined) return;
      fact("people", String(group.count));
      fact("route", (group.route?.stops ?? []).map((s) => s.floor + (s.waitSeconds > 0
        ? ` wait ${formatSeconds(s.waitSeconds)}s` : "")).join(", "));
      el("p", { class: "hint", text: "A group's route and size are changed in the text; Delete removes its line." },
        box);
    } else if ((selection.kind === "human") && d.movers.some((m) => m.name === selection.name && m.route != null)) {
      const mover = d.movers.find((m) => m.name === selection.name) as Mover;
      fact("type", mover.footprint?.type ?? "Human");
      fact("behaviour", mover.route?.behaviour ?? "?");
      fact("speed", `${formatSeconds(mover.route?.speed ?? 0)} m/s`);
      fact("start", `${formatSeconds(mover.route?.start ?? 0)} s`);
      const stops = (mover.route?.stops ?? []).flatMap((s) => (s.floor === null ? []
        : [{ floor: s.floor, waitSeconds: s.waitSeconds }]));
      this.renderStops(box, stops, mover.loop, false);
      const row = el("div", { class: "row" }, box);
      button("Draw route", "a new route: click floors for its stops", row, () => this.actions.startPath()).id =
        "draw-route";
      button("Extend route", "add stops after the last one by clicking floors", row,
        () => this.actions.startPath(true)).id = "extend-route";
    } else if (selection.kind === "human" || selection.kind === "dynamic") {
      const mover = d.movers.find((m) => m.name === selection.name);
      if (mover === undefined) return;
      fact("type", mover.footprint?.type ?? "Human");
      const points = mover.points.flatMap((p) => (p.floor === null ? [] : [{ floor: p.floor, seconds: p.seconds }]));
      this.renderPoints(box, points, mover.loop, false);
      const row = el("div", { class: "row" }, box);
      button("Draw path", "a new path: click floors for its points", row, () => this.actions.startPath());
      button("Extend path", "add points after the last one by clicking floors", row,
        () => this.actions.startPath(true)).id = "extend-path";
    } else if (selection.kind === "floor") {
      const floor = index.floors.get(selection.name);
      fact("type", floor?.type ?? "?");
      fact("cell", floor?.x === null || floor === undefined ? "not placed" : `${floor.x}, ${floor.y}`);
      el("p", { class: "hint", text: index.editableLayout
        ? "Delete removes the floor; the + strips on its sides add a wall."
        : layoutHint(index) }, box);
    } else if (selection.kind === "wall") {
      const wall = d.room?.walls.find((w) => w.name === selection.name);
      fact("on", wall === undefined ? "?" : `${wall.side} of ${wall.floor}`);
      el("p", { class: "hint", text: index.editableLayout ? "Delete removes the wall." : layoutHint(index) }, box);
    } else if (selection.kind === "goal") {
      const goal = d.mission?.goals.find((g) => g.index === Number(selection.name));
      fact("floor", goal?.floor ?? "?");
      fact("timeout", goal?.timeout == null ? "the mission's" : `${formatSeconds(goal.timeout)} s`);
    }
  }

  /** Finish, Cancel and Clear under a draft. */
  private draftButtons(box: HTMLElement, empty: boolean, clear: () => void): void {
    const row = el("div", { class: "row" }, box);
    button("Finish", "save it (Enter)", row, () => this.actions.finishPath()).id = "finish-draft";
    button("Cancel", "drop the drawing (Escape)", row, () => this.actions.cancelPath());
    button("Clear", "remove every floor and start again", row, clear, "clear-points").disabled = empty;
  }

  /** A route's stops: waits editable, stops removable, loop or once. */
  private renderStops(box: HTMLElement, stops: readonly StopSpec[], loop: boolean, drafting: boolean): void {
    const list = el("ol", { class: "points stops" }, box);
    list.id = "stops";
    stops.forEach((stop, i) => {
      const row = el("li", {}, list);
      row.dataset.stop = String(i);
      el("span", { text: stop.floor, class: "floor" }, row);
      el("span", { text: "wait" }, row);
      numberField(row, formatSeconds(stop.waitSeconds), "1",
        (value) => this.actions.editStops(stops.map((s, j) => (j === i ? { ...s, waitSeconds: value } : s)), loop),
        { class: "wait", title: "seconds the person waits at this stop" }).min = "0";
      el("span", { text: "s" }, row);
      const remove = button("×", "remove this stop", row, () =>
        this.actions.editStops(stops.filter((_, j) => j !== i), loop), "remove-stop");
      remove.disabled = !drafting && stops.length <= 1;
    });
    if (stops.length === 0) el("li", { class: "hint", text: "no stops yet: click a floor" }, list);
    const label = el("label", { class: "loop" }, box);
    const check = el("input", {}, label);
    check.type = "checkbox";
    check.id = "loop";
    check.checked = loop;
    label.append(" loop (else once)");
    check.addEventListener("change", () => this.actions.editStops([...stops], check.checked));
  }

  /** A crowd's size and rate: fields that change the draft, or the selected crowd at once. */
  private crowdFields(facts: HTMLElement, count: number, rate: number | null): void {
    const countBox = el("dd", {}, facts);
    facts.insertBefore(el("dt", { text: "people" }), countBox);
    const countField = numberField(countBox, String(count), "1", (value) => {
      if (Number.isInteger(value) && value >= 1) this.actions.editCrowd({ count: value });
    }, { title: "how many people the crowd has" });
    countField.id = "crowd-count";
    countField.min = "1";
    const rateBox = el("dd", {}, facts);
    facts.insertBefore(el("dt", { text: "rate" }), rateBox);
    const rateField = el("input", { title: "people a second who set off one after another; blank: all at once" },
      rateBox);
    rateField.type = "number";
    rateField.step = "0.1";
    rateField.min = "0";
    rateField.id = "crowd-rate";
    rateField.value = rate === null ? "" : String(rate);
    rateField.placeholder = "all at once";
    rateField.addEventListener("change", () => {
      const text = rateField.value.trim();
      const value = Number(text);
      if (text === "") this.actions.editCrowd({ rate: null });
      else if (Number.isFinite(value)) this.actions.editCrowd({ rate: value });
    });
    el("span", { text: " /s" }, rateBox);
  }

  private renderCrowdDraft(box: HTMLElement, draft: CrowdDraft): void {
    el("p", { text: draft.isNew ? `New crowd ${draft.name}` : `Areas of crowd ${draft.name}`, class: "title" }, box);
    el("p", { class: "hint", text: `Click floors, or drag a rectangle over them, for the ${draft.area} area (a `
      + "rectangle replaces it). Finish (Enter) saves the crowd, Escape cancels." }, box);
    const areas = el("div", { class: "row areas" }, box);
    for (const which of ["from", "to"] as const) {
      const b = button(`${which === "from" ? "From" : "To"} (${draft[which].length})`,
        `choose the floors the people ${which === "from" ? "start on" : "walk to"}`, areas,
        () => this.actions.editCrowd({ area: which }), `area-${which}`);
      b.id = `crowd-${which}`;
      b.classList.toggle("active", draft.area === which);
    }
    const facts = el("dl", {}, box);
    this.crowdFields(facts, draft.count, draft.rate);
    for (const which of ["from", "to"] as const) {
      el("dt", { text: which }, facts);
      el("dd", { text: draft[which].length === 0 ? "–" : draft[which].join(", "), class: `area-floors ${which}` },
        facts);
    }
    this.draftButtons(box, draft.from.length === 0 && draft.to.length === 0,
      () => this.actions.editCrowd({ [draft.area]: [] }));
  }

  /** A trajectory's points: times editable, points removable, loop or once. */
  private renderPoints(box: HTMLElement, points: readonly PointSpec[], loop: boolean, drafting: boolean): void {
    const list = el("ol", { class: "points" }, box);
    list.id = "points";
    points.forEach((point, i) => {
      const row = el("li", {}, list);
      row.dataset.point = String(i);
      el("span", { text: point.floor, class: "floor" }, row);
      numberField(row, formatSeconds(point.seconds), "1",
        (value) => this.actions.editPoints(points.map((p, j) => (j === i ? { ...p, seconds: value } : p)), loop),
        { class: "seconds", title: "time of this point, seconds" }).min = "0";
      el("span", { text: "s" }, row);
      const remove = button("×", "remove this point", row, () =>
        this.actions.editPoints(points.filter((_, j) => j !== i), loop), "remove-point");
      remove.disabled = !drafting && points.length <= 1;
    });
    if (points.length === 0) el("li", { class: "hint", text: "no points yet: click a floor" }, list);
    const label = el("label", { class: "loop" }, box);
    const check = el("input", {}, label);
    check.type = "checkbox";
    check.id = "loop";
    check.checked = loop;
    label.append(" loop (else once)");
    check.addEventListener("change", () => this.actions.editPoints([...points], check.checked));
  }

  private renderMission(index: RoomIndex, selection: Selection | null, issues: readonly Issue[]): void {
    const mission = index.diagram.mission;
    this.missionHead.replaceChildren();
    this.goals.replaceChildren();
    const panel = byId("mission-panel");
    panel.classList.toggle("has-issue", issues.some((i) => i.kind === "mission"));
    if (mission === null) {
      el("p", { class: "hint", text: "No mission: write `mission NAME { goto FLOOR }` in the text to add goals." },
        this.missionHead);
      return;
    }
    const facts = el("dl", {}, this.missionHead);
    for (const [term, value] of [["name", mission.name], ["tolerance", metres(mission.tolerance)],
      ["timeout", `${formatSeconds(mission.taskTimeout)} s per goal`]] as const) {
      el("dt", { text: term }, facts);
      el("dd", { text: value }, facts);
    }
    const count = mission.goals.length;
    mission.goals.forEach((goal, i) => {
      const row = el("li", {}, this.goals);
      row.dataset.index = String(goal.index);
      row.classList.toggle("selected", selection?.kind === "goal" && selection.name === String(goal.index));
      row.classList.toggle("has-issue", issues.some((issue) => issue.kind === "goal" && issue.index === goal.index));
      const name = el("span", { class: "goal-name", text: `${i + 1}. ${goal.floor ?? "?"}` +
        (goal.timeout === null ? "" : ` within ${formatSeconds(goal.timeout)} s`) }, row);
      name.addEventListener("click", () => this.actions.select({ kind: "goal", name: String(goal.index) }));
      const up = button("↑", "earlier", row,
        () => this.actions.moveGoal(goal.index, mission.goals[i - 1]?.index ?? 0), "up");
      up.disabled = i === 0;
      const down = button("↓", "later", row, () =>
        this.actions.moveGoal(goal.index, mission.goals[i + 1]?.index ?? goal.index), "down");
      down.disabled = i === count - 1;
      button("×", "remove this goal", row, () => this.actions.removeGoal(goal.index), "remove");
    });
  }

  private renderMonitor(index: RoomIndex, issues: readonly Issue[]): void {
    const monitor = index.diagram.monitor;
    this.monitor.replaceChildren();
    byId("monitor-panel").classList.toggle("has-issue", issues.some((i) => i.kind === "monitor"));
    if (monitor === null) {
      el("p", { class: "hint", text: "No monitor block: the defaults apply." }, this.monitor);
      return;
    }
    const facts = el("dl", {}, this.monitor);
    for (const [term, value, title] of [
      ["close", metres(monitor.close), "closer than this to a human is CLOSE"],
      ["collision", metres(monitor.collision), "closer than this is a COLLISION"],
      ["maxHumanCollisions", String(monitor.maxHumanCollisions), "collisions with humans the run may have"],
    ] as const) {
      el("dt", { text: term, title }, facts);
      el("dd", { text: value }, facts);
    }
  }

  private renderIssues(issues: readonly Issue[]): void {
    this.issues.replaceChildren();
    const errors = issues.filter((i) => i.severity === "error").length;
    this.issueCount.textContent = issues.length === 0 ? "none"
      : `${errors} error${errors === 1 ? "" : "s"}, ${issues.length - errors} other`;
    for (const issue of issues.slice(0, MAX_ISSUE_ROWS)) {
      const row = el("li", { class: `issue ${issue.severity}` }, this.issues);
      row.dataset.element = issue.element ?? "";
      row.dataset.kind = issue.kind ?? "";
      if (issue.index !== null) row.dataset.index = String(issue.index);
      el("span", { class: "severity", text: issue.severity }, row);
      el("span", { class: "where", text: `${issue.line}:${issue.column}` }, row);
      el("span", { class: "message", text: issue.message }, row);
      row.addEventListener("click", () => this.actions.showIssue(issue));
    }
    if (issues.length > MAX_ISSUE_ROWS) {
      el("li", { class: "hint", text: `… and ${issues.length - MAX_ISSUE_ROWS} more` }, this.issues);
    }
  }
}

export function goalNumber(index: RoomIndex, goalIndex: number): number {
  return (index.diagram.mission?.goals.findIndex((g) => g.index === goalIndex) ?? -1) + 1;
}

export function layoutHint(index: RoomIndex): string {
  if (index.occupancy !== null) {
    return "The floors of this room are the free blocks of its occupancy map: edit the map (or floorSize) to change "
      + "them.";
  }
  return index.form === "map"
    ? "The floors and walls of this room come from its map: edit the map in the text to change them."
    : "The floors and walls of this room come from its size (`size C x R`): change the size in the text.";
}

