// SPDX-License-Identifier: EPL-2.0
// What a click or a drag on the diagram means with the active tool: place furniture, add a goal, add a point to
// the path or a stop to the route being drawn, add a floor to a crowd's area (or, dragged, a rectangle of floors),
// add a floor on a ghost cell or a wall on a side strip, select, or move furniture and the robot to the floor
// they are dropped on. Floors are found from the pointer's world position (RoomIndex), not
// from the element under it, so a click on a table still finds the table's floor.
import type { Editor } from "../editor";
import type { Selection } from "../model";
import { KINDS, nameKey } from "../model";
import type { Side } from "../types";
import { SIDES } from "../types";
import { appendPoint } from "./path";
import { appendStop, floorsIn, setArea, toggleFloor } from "./people";
import type { DragSession, PointerHandlers } from "./pointer";

const isSide = (value: string): value is Side => (SIDES as readonly string[]).includes(value);

export class Gestures implements PointerHandlers {
  constructor(private readonly editor: Editor, private readonly where: HTMLElement) {}

  click(target: Element | null, world: [number, number], event: PointerEvent): void {
    const index = this.editor.index;
    if (index === null) return;
    const tool = this.editor.tool;
    const floor = index.floorAt(world[0], world[1]);
    if (tool.kind === "place") {
      if (floor === undefined) {
        return this.editor.chrome.toast(`Click a floor to place the ${tool.type.name}.`, "error");
      }
      const keep = event.shiftKey;
      void this.editor.apply({ op: "addObject", name: index.fresh(tool.type.name.toLowerCase()), type: tool.type.name,
        floor: floor.name }).then((ok) => {
        if (ok && !keep) this.editor.setTool({ kind: "select" });
      });
      return;
    }
    if (tool.kind === "goal") {
      if (floor === undefined) return this.editor.chrome.toast("Click a floor to make it a goal.", "error");
      const keep = event.shiftKey;
      const at = index.diagram.mission?.goals.length ?? 0;
      void this.editor.apply({ op: "addGoal", floor: floor.name, index: at, timeoutSeconds: null }).then((ok) => {
        if (ok && !keep) this.editor.setTool({ kind: "select" });
      });
      return;
    }
    if (tool.kind === "path") {
      if (floor === undefined) {
        return this.editor.chrome.toast("Control points are floor centres: click a floor.", "error");
      }
      this.editor.setTool({ kind: "path", draft: appendPoint(index, tool.draft, floor.name) });
      return;
    }
    if (tool.kind === "route") {
      if (floor === undefined) return this.editor.chrome.toast("A route's stops are floors: click a floor.", "error");
      this.editor.setTool({ kind: "route", draft: appendStop(tool.draft, floor.name) });
      return;
    }
    if (tool.kind === "crowd") {
      if (floor === undefined) return this.editor.chrome.toast("A crowd's areas are floors: click a floor.", "error");
      this.editor.setTool({ kind: "crowd", draft: toggleFloor(tool.draft, floor.name) });
      return;
    }
    const side = target?.getAttribute("data-add-wall");
    const onFloor = target?.getAttribute("data-floor");
    if (side != null && onFloor != null && isSide(side)) {
      void this.editor.apply({ op: "addWall", name: index.freshWall(onFloor, side), floor: onFloor, side });
      return;
    }
    const kind = target?.getAttribute("data-kind") ?? null;
    if (kind === "ghost" && target !== null && target !== undefined) {
      const neighbours: Partial<Record<Side, string>> = {};
      for (const pair of (target.getAttribute("data-neighbours") ?? "").split(" ")) {
        const [s, name] = pair.split(":");
        if (s !== undefined && name !== undefined && isSide(s)) neighbours[s] = name;
      }
      const name = target.getAttribute("data-name") ?? index.fresh("F");
      void this.editor.apply({ op: "addFloor", name, neighbours }).then((ok) => {
        if (ok) this.editor.select({ kind: "floor", name });
      });
      return;
    }
    if (kind === "goal") {
      this.editor.select({ kind: "goal", name: target?.getAttribute("data-index") ?? "0" });
    } else if (kind !== null && KINDS.has(kind)) {
      this.editor.select({ kind: kind as Selection["kind"], name: target?.getAttribute("data-name") ?? "" });
    } else {
      this.editor.select(null);
    }
  }

  /** Furniture and the robot drag onto another floor; the drop snaps to the floor under the pointer. */
  drag(target: Element | null, world: [number, number]): DragSession | null {
    const index = this.editor.index;
    const tool = this.editor.tool;
    if (index !== null && tool.kind === "crowd") {
      // a rectangle over floors: they become the area being chosen
      const start = world;
      const area = tool.draft.area;
      return {
        move: (at) => this.editor.diagram.areaPreview(start, at, area),
        drop: (at) => {
          this.editor.diagram.clearPreview();
          const floors = floorsIn(index, start, at);
          const current = this.editor.tool;
          if (floors.length === 0) {
            this.editor.chrome.toast("The rectangle holds no floor.", "error");
          } else if (current.kind === "crowd") {
            this.editor.setTool({ kind: "crowd", draft: setArea(current.draft, floors) });
          }
        },
        cancel: () => this.editor.diagram.clearPreview(),
      };
    }
    if (index === null || target === null || tool.kind !== "select") return null;
    const kind = target.getAttribute("data-kind");
    const name = target.getAttribute("data-name") ?? "";
    const d = index.diagram;
    const item = kind === "robot" ? d.robot : kind === "object" ? d.objects.find((o) => o.name === name) : undefined;
    if (item === undefined || item === null) return null;
    // a type the catalogues do not know (an error in the text) still moves, shown as a small box
    const footprint = item.footprint ?? { type: "?", shape: "box", sizeX: 0.5, sizeY: 0.5, height: 0.5, colour: null };
    // selecting redraws: the pressed element is replaced, so the drawn one is looked up by name
    this.editor.select({ kind: kind as Selection["kind"], name });
    const source = (): Element | null => this.editor.diagram.element(nameKey(name)) ?? null;
    source()?.classList.add("drag-source");
    const finish = (): void => {
      this.editor.diagram.clearPreview();
      source()?.classList.remove("drag-source");
    };
    return {
      move: (world) => {
        const floor = index.floorAt(world[0], world[1]);
        const at: [number, number] = floor === undefined ? world : [floor.centreX, floor.centreY];
        this.editor.diagram.dragPreview(at, footprint, item.yaw, floor?.name ?? null);
      },
      drop: (world) => {
        finish();
        const floor = index.floorAt(world[0], world[1]);
        // off the floors, or back where it was: nothing to do
        if (floor === undefined || floor.name === item.floor) return;
        void this.editor.apply({ op: "moveObject", name: item.name, floor: floor.name });
      },
      cancel: finish,
    };
  }

  hover(world: [number, number] | null): void {
    if (world === null || this.editor.index === null) {
      this.where.textContent = "";
      return;
    }
    const floor = this.editor.index.floorAt(world[0], world[1]);
    this.where.textContent = `${floor?.name ?? "–"} · (${world[0].toFixed(2)}, ${world[1].toFixed(2)}) m`;
  }
}
