// SPDX-License-Identifier: EPL-2.0
// The editor: the server's State, the selection and the active tool, and every gesture turned into operations.
// The page never changes the diagram itself: each edit is sent to the server and the State it answers is drawn,
// so what is shown is always what the engine made of the text (a refused edit changes nothing but the toast).
import type { Api } from "./api";
import { ApiError } from "./api";
import type { Chrome } from "./chrome";
import type { DiagramView } from "./draw/diagram";
import type { CrowdDraft, Selection, Tool } from "./model";
import { goalKey, issuesByKey, KINDS, nameKey } from "./model";
import type { Actions } from "./panels";
import { layoutHint, Panels } from "./panels";
import { RoomIndex } from "./room";
import { draftOf, finishOperation, newDynamicDraft, newHumanDraft } from "./tools/path";
import {
  crowdDraftOf, crowdOperation, crowdProblem, newCrowdDraft, routeDraftOf, routeOperation,
} from "./tools/people";
import type { Issue, Operation, PaletteType, PointSpec, State, Status, StopSpec } from "./types";

export const POLL_MS = 1000;


function message(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}

/** Degrees in [0, 360), without float dust. */
function normalYaw(degrees: number): number {
  const yaw = ((degrees % 360) + 360) % 360;
  return Math.round(yaw * 1000) / 1000;
}

export class Editor implements Actions {
  state: State | null = null;
  index: RoomIndex | null = null;
  selection: Selection | null = null;
  tool: Tool = { kind: "select" };
  /** The latest Status (from a State or the poll): dirty decides the unload warning. */
  status: Status | null = null;
  private issues = new Map<string, Issue[]>();
  private readonly panels: Panels;
  private fitted = false;
  private polling = false;

  constructor(private readonly api: Api, readonly diagram: DiagramView, readonly chrome: Chrome) {
    this.panels = new Panels(this);
  }

  async start(): Promise<void> {
    if (!this.api.hasToken) {
      this.chrome.toast("This page needs its token: open it with the URL that `rei edit` printed.", "error");
    }
    await this.run(this.api.state());
    window.setInterval(() => void this.poll(), POLL_MS);
  }

  // ---- talking to the server ------------------------------------------------------------------------------

  private accept(state: State): void {
    this.state = state;
    this.status = state;
    this.index = new RoomIndex(state.diagram, state.occupancy ?? null);
    this.issues = issuesByKey(state.issues);
    this.selection = this.existing(this.selection);
    const tool = this.tool;
    if (tool.kind === "path" && !tool.draft.isNew && !state.diagram.movers.some((m) => m.name === tool.draft.name)) {
      this.tool = { kind: "select" };
    }
    // a draft of something an undo or a reload took away has nothing left to change
    if (tool.kind === "route" && !state.diagram.movers.some((m) => m.name === tool.draft.name && m.route != null)) {
      this.tool = { kind: "select" };
    }
    if (tool.kind === "crowd" && !tool.draft.isNew
      && !(state.diagram.crowds ?? []).some((c) => c.name === tool.draft.name)) {
      this.tool = { kind: "select" };
    }
    this.chrome.setFile(state.file);
    this.chrome.status(state);
    this.redraw();
    if (!this.fitted) {
      this.fitted = true;
      this.diagram.fit();
    }
    if (state.notice !== null && state.notice !== "") this.chrome.toast(state.notice);
  }

  /** Sends a request whose answer is a State; a refusal (422, 409, ...) is a toast and nothing else. */
  private async run(request: Promise<State>): Promise<boolean> {
    try {
      this.accept(await request);
      return true;
    } catch (error) {
      this.chrome.toast(message(error), "error");
      if (error instanceof ApiError && error.status === 0) this.chrome.connected(false);
      return false;
    }
  }

  apply(...operations: Operation[]): Promise<boolean> {
    return this.run(this.api.apply(operations));
  }

  command(name: "undo" | "redo" | "save" | "reload" | "keep"): Promise<boolean> {
    return this.run(this.api.command(name));
  }

  /** About once a second: the cheap Status; the State only when its version moved (an edit elsewhere, a reload). */
  async poll(): Promise<void> {
    if (this.polling || this.api.pending > 0) return;
    this.polling = true;
    try {
      const status = await this.api.status();
      this.status = status;
      this.chrome.status(status);
      if (this.state === null || status.version !== this.state.version) this.accept(await this.api.state());
    } catch (error) {
      this.chrome.connected(false, error instanceof ApiError && error.status === 0 ? "the server does not answer"
        : message(error));
    } finally {
      this.polling = false;
    }
  }

  // ---- drawing ------------------------------------------------------------------------------------------

  redraw(): void {
    const { state, index } = this;
    if (state === null || index === null) return;
    const tool = this.tool;
    this.diagram.render({ index, issues: this.issues, selection: this.selection,
      draft: tool.kind === "path" ? tool.draft : null, routeDraft: tool.kind === "route" ? tool.draft : null,
      crowdDraft: tool.kind === "crowd" ? tool.draft : null });
    this.panels.render(state, index, this.selection, this.tool);
    this.chrome.tools(index, this.selection, this.tool);
    this.chrome.showHint(this.hint(index));
  }

  private hint(index: RoomIndex): string {
    const tool = this.tool;
    if (tool.kind === "place") {
      return `Click a floor to place a ${tool.type.name} (Shift-click to place more). Escape stops.`;
    }
    if (tool.kind === "goal") {
      return "Click a floor to add it as the mission's last goal (Shift-click for more). Escape stops.";
    }
    if (tool.kind === "path") {
      return "Click floors to add control points. Enter or Finish saves the path, Escape cancels.";
    }
    if (tool.kind === "route") {
      return "Click floors to add stops to the route. Enter or Finish saves it, Escape cancels.";
    }
    if (tool.kind === "crowd") {
      return `Click floors or drag a rectangle over them for the crowd's ${tool.draft.area} area `
        + "(From / To in the side panel switch). Enter or Finish saves the crowd, Escape cancels.";
    }
    if (index.diagram.room === null) return "This test case has no room.";
    if (!index.editableLayout) return layoutHint(index);
    return "Click a dashed cell to add a floor there; select a floor for its add-wall strips; Delete removes.";
  }

  /** The selection if its element is still in the diagram (after an edit, undo or reload), else null. */
  private existing(selection: Selection | null): Selection | null {
    if (selection === null || this.index === null) return null;
    const d = this.index.diagram;
    const name = selection.name;
    const found = selection.kind === "goal" ? d.mission?.goals.some((g) => String(g.index) === name)
      : selection.kind === "floor" ? this.index.floors.has(name)
        : selection.kind === "wall" ? d.room?.walls.some((w) => w.name === name)
          : selection.kind === "robot" ? d.robot?.name === name
            : selection.kind === "object" ? d.objects.some((o) => o.name === name)
              : selection.kind === "crowd" ? (d.crowds ?? []).some((c) => c.name === name)
                : selection.kind === "group" ? (d.groups ?? []).some((g) => g.name === name)
                  : d.movers.some((m) => m.name === name);
    return found === true ? selection : null;
  }

  // ---- selection and tools ------------------------------------------------------------------------------

  select(selection: Selection | null): void {
    this.selection = selection;
    this.redraw();
  }

  setTool(tool: Tool): void {
    this.tool = tool;
    this.redraw();
  }

  choosePalette(type: PaletteType): void {
    const index = this.index;
    if (index === null) return;
    const current = this.tool;
    if (current.kind === "place" && current.type.name === type.name) return this.setTool({ kind: "select" });
    if (type.category === "human" || type.category === "dynamic") {
      this.selection = null;
      const draft = type.category === "human" ? newHumanDraft(index, type.name) : newDynamicDraft(index, type);
      return this.setTool({ kind: "path", draft });
    }
    if (type.category === "object") return this.setTool({ kind: "place", type });
    this.chrome.toast(`${type.name} is a ${type.category} type: it cannot be placed from the palette`, "error");
  }

  toggleGoalTool(): void {
    if (this.state?.diagram.mission === null) {
      this.chrome.toast("This test case has no mission to add goals to.", "error");
      return;
    }
    this.setTool(this.tool.kind === "goal" ? { kind: "select" } : { kind: "goal" });
  }

  /** Escape: leaves the tool, or else the selection. */
  escape(): void {
    if (this.tool.kind !== "select") this.setTool({ kind: "select" });
    else this.select(null);
  }

  showIssue(issue: Issue): void {
    const kind = issue.kind;
    // the kind drawn on the element wins over the issue's: the element is what gets selected
    const drawn = issue.element === null ? null
      : this.diagram.element(nameKey(issue.element))?.getAttribute("data-kind") ?? null;
    if (kind === "goal" && issue.index !== null) this.select({ kind: "goal", name: String(issue.index) });
    else if (issue.element !== null && (drawn ?? kind) !== null && KINDS.has(drawn ?? kind ?? "")) {
      this.select({ kind: (drawn ?? kind) as Selection["kind"], name: issue.element });
    } else {
      return;
    }
    // bring it into view when it is off screen (a big room)
    const key = kind === "goal" ? goalKey(issue.index ?? 0) : nameKey(issue.element ?? "");
    const anchor = this.index === null ? null : this.diagram.anchor(key, this.index);
    if (anchor === null) return;
    const view = this.diagram.view;
    const [sx, sy] = view.toScreen(anchor.x, anchor.y);
    if (sx < 0 || sy < 0 || sx > view.width || sy > view.height) view.pan(view.width / 2 - sx, view.height / 2 - sy);
  }

  // ---- edits --------------------------------------------------------------------------------------------

  private selectedItem(): { name: string; yaw: number } | null {
    const selection = this.selection;
    const d = this.index?.diagram;
    if (selection === null || d === undefined) return null;
    if (selection.kind === "robot") return d.robot;
    if (selection.kind === "object") return d.objects.find((o) => o.name === selection.name) ?? null;
    return null;
  }

  rotate(delta: number): void {
    const item = this.selectedItem();
    if (item === null) return;
    void this.apply({ op: "rotateObject", name: item.name, yawDegrees: normalYaw(item.yaw + delta) });
  }

  setYaw(degrees: number): void {
    const item = this.selectedItem();
    if (item !== null) void this.apply({ op: "rotateObject", name: item.name, yawDegrees: normalYaw(degrees) });
  }

  async deleteSelected(): Promise<void> {
    const selection = this.selection;
    const index = this.index;
    if (selection === null || index === null || this.drafting) return;
    let operation: Operation;
    switch (selection.kind) {
      case "object":
      case "human":
      case "dynamic":
      case "crowd":
      case "group":
        operation = { op: "deleteObject", name: selection.name };
        break;
      case "goal":
        operation = { op: "removeGoal", index: Number(selection.name) };
        break;
      case "floor":
      case "wall":
        if (!index.editableLayout) {
          this.chrome.toast(layoutHint(index), "error");
          return;
        }
        operation = selection.kind === "floor" ? { op: "removeFloor", name: selection.name }
          : { op: "removeWall", name: selection.name };
        break;
      case "robot":
        this.chrome.toast("A room has exactly one robot: drag it to another floor instead.", "error");
        return;
      default:
        return;
    }
    if (await this.apply(operation)) this.select(null);
  }

  moveGoal(from: number, to: number): void {
    if (from !== to) void this.apply({ op: "moveGoal", from, to });
  }

  removeGoal(index: number): void {
    void this.apply({ op: "removeGoal", index });
  }

  // ---- trajectories -------------------------------------------------------------------------------------

  /** A path, a route or a crowd is being drawn: the other edits wait until it is finished or cancelled. */
  get drafting(): boolean {
    return this.tool.kind === "path" || this.tool.kind === "route" || this.tool.kind === "crowd";
  }

  /** Draws the selected mover's path anew (or extends it); a person who walks a route gets its route drawn. */
  startPath(extend = false): void {
    const selection = this.selection;
    if (selection?.kind === "crowd") return this.startCrowd(true);
    const mover = this.index?.diagram.movers.find((m) => m.name === selection?.name);
    if (mover === undefined) {
      this.chrome.toast("Select a human (or a moving object) first.", "error");
      return;
    }
    if (mover.route != null) {
      this.setTool({ kind: "route", draft: routeDraftOf(mover, extend) });
      return;
    }
    this.setTool({ kind: "path", draft: draftOf(mover, extend) });
  }

  /** Changes the stops of the route being drawn, or of the selected person's route at once. */
  editStops(stops: StopSpec[], loop: boolean): void {
    const tool = this.tool;
    if (tool.kind === "route") {
      this.setTool({ kind: "route", draft: { ...tool.draft, stops, loop } });
      return;
    }
    const mover = this.index?.diagram.movers.find((m) => m.name === this.selection?.name);
    const operation = mover === undefined ? null : routeOperation(mover, stops, loop);
    if (operation !== null) void this.apply(operation);
  }

  /** A new crowd, or the selected crowd's areas (`existing`): clicks and rectangles choose floors. */
  startCrowd(existing = false): void {
    const index = this.index;
    if (index === null) return;
    const selection = this.selection;
    const crowd = existing && selection?.kind === "crowd"
      ? index.diagram.crowds?.find((c) => c.name === selection.name) : undefined;
    if (crowd === undefined) this.selection = null;
    this.setTool({ kind: "crowd", draft: crowd === undefined ? newCrowdDraft(index) : crowdDraftOf(crowd) });
  }

  /** Changes the crowd being placed, or the selected crowd's size or rate at once. */
  editCrowd(change: Partial<CrowdDraft>): void {
    const tool = this.tool;
    if (tool.kind === "crowd") {
      this.setTool({ kind: "crowd", draft: { ...tool.draft, ...change } });
      return;
    }
    const selection = this.selection;
    const crowd = selection?.kind === "crowd"
      ? this.index?.diagram.crowds?.find((c) => c.name === selection.name) : undefined;
    if (crowd !== undefined) void this.apply(crowdOperation({ ...crowdDraftOf(crowd), ...change }));
  }

  editPoints(points: PointSpec[], loop: boolean): void {
    const tool = this.tool;
    if (tool.kind === "path") {
      this.setTool({ kind: "path", draft: { ...tool.draft, points, loop } });
      return;
    }
    const selection = this.selection;
    if (selection !== null && (selection.kind === "human" || selection.kind === "dynamic")) {
      void this.apply({ op: "setTrajectory", name: selection.name, points, loop });
    }
  }

  /** Finish (Enter): saves the path, route or crowd being drawn as one operation. */
  async finishPath(): Promise<void> {
    const tool = this.tool;
    if (tool.kind === "route") return this.finishRoute(tool.draft.name, tool.draft.stops, tool.draft.loop);
    if (tool.kind === "crowd") return this.finishCrowd(tool.draft);
    if (tool.kind !== "path") return;
    if (tool.draft.points.length === 0) {
      this.chrome.toast("Click at least one floor for the path first.", "error");
      return;
    }
    if (await this.apply(finishOperation(tool.draft))) {
      const kind = this.index?.diagram.movers.find((m) => m.name === tool.draft.name)?.kind ?? tool.draft.kind;
      this.tool = { kind: "select" };
      this.select({ kind, name: tool.draft.name });
    }
  }

  private async finishRoute(name: string, stops: StopSpec[], loop: boolean): Promise<void> {
    const mover = this.index?.diagram.movers.find((m) => m.name === name);
    if (stops.length === 0) {
      this.chrome.toast("Click at least one floor for the route first.", "error");
      return;
    }
    const operation = mover === undefined ? null : routeOperation(mover, stops, loop);
    if (operation !== null && await this.apply(operation)) {
      this.tool = { kind: "select" };
      this.select({ kind: "human", name });
    }
  }

  private async finishCrowd(draft: CrowdDraft): Promise<void> {
    const problem = crowdProblem(draft);
    if (problem !== null) {
      this.chrome.toast(problem, "error");
      return;
    }
    if (await this.apply(crowdOperation(draft))) {
      this.tool = { kind: "select" };
      this.select({ kind: "crowd", name: draft.name });
    }
  }

  cancelPath(): void {
    if (this.drafting) this.setTool({ kind: "select" });
  }
}
