// SPDX-License-Identifier: EPL-2.0
// Floors, the ghost cells where a graph room can grow, and the floors' names. A room can have 10,000 floors,
// so this layer is rebuilt only when the floors or walls change (not on every selection or issue), each floor
// is one <rect> with no listener of its own (the page listens once on the SVG), names are drawn only for
// rooms up to LABELLED_FLOORS floors, and marking (issues, selection) touches only the marked floors.
import { FLOOR, FLOOR_EDGE } from "../../draw/colours";
import type { RoomIndex } from "../room";
import { clear, r, svg, Y } from "../svg";

/** Above this many floors their names would be unreadable clutter and cost more DOM than they are worth. */
export const LABELLED_FLOORS = 400;

export class FloorLayer {
  private signature = "";
  private readonly rects = new Map<string, SVGRectElement>();
  /** Class name → floors that have it now, so that clearing it is O(marked), not O(floors). */
  private readonly marked = new Map<string, Set<string>>();
  private ghostCount = 0;

  constructor(private readonly floors: SVGGElement, private readonly ghosts: SVGGElement,
              private readonly labels: SVGGElement) {}

  get ghostsShown(): number {
    return this.ghostCount;
  }

  /** Rebuilds when the room's floors or walls changed; true when it did. */
  update(index: RoomIndex): boolean {
    const room = index.diagram.room;
    const signature = room === null ? "" : signatureOf(index);
    if (signature === this.signature) return false;
    this.signature = signature;
    this.rects.clear();
    this.marked.clear();
    clear(this.floors);
    clear(this.ghosts);
    clear(this.labels);
    this.ghostCount = 0;
    if (room === null) return true;
    const s = index.size;
    const half = s / 2;
    const fragment = document.createDocumentFragment();
    for (const floor of index.placed) {
      const rect = svg("rect", {
        x: r(floor.centreX - half), y: r(Y(floor.centreY + half)), width: r(s), height: r(s),
        fill: FLOOR, stroke: FLOOR_EDGE, "data-kind": "floor", "data-name": floor.name,
      }, fragment);
      this.rects.set(floor.name, rect);
    }
    this.floors.appendChild(fragment);
    if (index.placed.length <= LABELLED_FLOORS) {
      const labels = document.createDocumentFragment();
      for (const floor of index.placed) {
        const text = svg("text", { x: r(floor.centreX - half + s * 0.06), y: r(Y(floor.centreY + half - s * 0.06)),
          "dominant-baseline": "hanging", class: "floor-name" }, labels);
        text.textContent = floor.name;
      }
      this.labels.appendChild(labels);
    }
    if (index.editableLayout) {
      const reserved = new Set<string>();
      const ghosts = document.createDocumentFragment();
      for (const ghost of index.ghosts()) {
        const name = index.freshFloor(ghost, reserved);
        reserved.add(name);
        svg("rect", {
          x: r(ghost.centreX - half + s * 0.04), y: r(Y(ghost.centreY + half - s * 0.04)), width: r(s * 0.92),
          height: r(s * 0.92), class: "ghost", "data-kind": "ghost", "data-name": name,
          "data-cell": `${ghost.x},${ghost.y}`,
          "data-neighbours": Object.entries(ghost.neighbours).map(([side, floor]) => `${side}:${floor}`).join(" "),
        }, ghosts);
        this.ghostCount += 1;
      }
      this.ghosts.appendChild(ghosts);
    }
    return true;
  }

  /** Gives exactly `names` the class (issues, selection, drop target), removing it from the others. */
  mark(className: string, names: Iterable<string>): void {
    const now = new Set<string>();
    for (const name of names) if (this.rects.has(name)) now.add(name);
    const before = this.marked.get(className) ?? new Set<string>();
    for (const name of before) if (!now.has(name)) this.rects.get(name)?.classList.remove(className);
    for (const name of now) if (!before.has(name)) this.rects.get(name)?.classList.add(className);
    this.marked.set(className, now);
  }

  rect(name: string): SVGRectElement | undefined {
    return this.rects.get(name);
  }
}

/** What the floor layer is drawn from; O(floors + walls) to build, cheaper than redrawing 10,000 rects. */
function signatureOf(index: RoomIndex): string {
  const room = index.diagram.room;
  if (room === null) return "";
  const parts: string[] = [room.form, String(room.floorSize)];
  for (const floor of room.floors) parts.push(`${floor.name}@${floor.x},${floor.y}`);
  parts.push("|");
  for (const wall of room.walls) parts.push(`${wall.floor}/${wall.side}`);
  return parts.join(" ");
}
