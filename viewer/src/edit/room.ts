// SPDX-License-Identifier: EPL-2.0
// Lookups over one diagram, built once per state in O(n): floors by name and by cell, the cells where a graph
// room can grow (ghosts), and every name in use. Hit-testing goes through the cell index, not through the
// DOM, so a drop or a tool click finds its floor in O(1) even on a 100 x 100 room and even when an object or
// a label covers the floor.
import type { Diagram, FloorCell, Occupancy, Side } from "./types";
import { SIDES } from "./types";

export interface PlacedFloor extends FloorCell {
  x: number;
  y: number;
  centreX: number;
  centreY: number;
}

export interface Ghost {
  /** Cell indices (may be -1 or columns: one step outside the laid-out room). */
  x: number;
  y: number;
  centreX: number;
  centreY: number;
  /** The existing floors next to the cell, by the side of the new floor they are on. */
  neighbours: Partial<Record<Side, string>>;
}

/** Cell offset of the neighbour on each side (y up). */
export const STEP: Readonly<Record<Side, readonly [number, number]>> = {
  top: [0, 1], right: [1, 0], bottom: [0, -1], left: [-1, 0],
};
export const OPPOSITE: Readonly<Record<Side, Side>> = { top: "bottom", right: "left", bottom: "top", left: "right" };

const key = (x: number, y: number): string => `${x},${y}`;

export function placed(floor: FloorCell): floor is PlacedFloor {
  return floor.x !== null && floor.y !== null && floor.centreX !== null && floor.centreY !== null;
}

export class RoomIndex {
  readonly floors = new Map<string, FloorCell>();
  readonly placed: PlacedFloor[] = [];
  private readonly cells = new Map<string, PlacedFloor>();
  /** Sides of floors that carry a wall: `floor/side`. */
  private readonly walled = new Set<string>();
  readonly names = new Set<string>();
  readonly size: number;
  /** Where cell (0, 0) starts in metres: cell i covers [origin + i*size, origin + (i+1)*size). */
  private readonly originX: number;
  private readonly originY: number;

  /** `occupancy`: the room is made from an occupancy map, whose free blocks are its floors. */
  constructor(readonly diagram: Diagram, readonly occupancy: Occupancy | null = null) {
    const room = diagram.room;
    this.size = room !== null && room.floorSize > 0 ? room.floorSize : 1;
    let originX = 0;
    let originY = 0;
    for (const floor of room?.floors ?? []) {
      this.floors.set(floor.name, floor);
      this.names.add(floor.name);
      if (!placed(floor)) continue;
      this.placed.push(floor);
      this.cells.set(key(floor.x, floor.y), floor);
      originX = floor.centreX - (floor.x + 0.5) * this.size;
      originY = floor.centreY - (floor.y + 0.5) * this.size;
    }
    this.originX = originX;
    this.originY = originY;
    for (const wall of room?.walls ?? []) {
      this.names.add(wall.name);
      this.walled.add(`${wall.floor}/${wall.side}`);
    }
    for (const item of diagram.objects) this.names.add(item.name);
    if (diagram.robot !== null) this.names.add(diagram.robot.name);
    for (const mover of diagram.movers) this.names.add(mover.name);
    if (room !== null) this.names.add(room.name);
    this.names.add(diagram.testCase);
    if (diagram.mission !== null) this.names.add(diagram.mission.name);
  }

  get form(): string {
    return this.diagram.room?.form ?? "grid";
  }

  /** Floors and walls are statements of the text only in a floor graph; elsewhere the size or map makes them. */
  get editableLayout(): boolean {
    return this.form === "graph" && this.occupancy === null;
  }

  /** Where the occupancy map's picture lies, in the diagram's metres: cell (0, 0) starts at the map's origin. */
  pictureBox(): [number, number, number, number] | null {
    const occupancy = this.occupancy;
    if (occupancy === null) return null;
    const [x0 = 0, y0 = 0, x1 = 0, y1 = 0] = occupancy.extent;
    const [ox = 0, oy = 0] = occupancy.origin;
    const dx = this.placed.length > 0 ? this.originX - ox : 0;
    const dy = this.placed.length > 0 ? this.originY - oy : 0;
    return [x0 + dx, y0 + dy, x1 + dx, y1 + dy];
  }

  cell(x: number, y: number): PlacedFloor | undefined {
    return this.cells.get(key(x, y));
  }

  /** The floor under a world point, if any. */
  floorAt(wx: number, wy: number): PlacedFloor | undefined {
    const [cx, cy] = this.cellAt(wx, wy);
    return this.cell(cx, cy);
  }

  cellAt(wx: number, wy: number): [number, number] {
    return [Math.floor((wx - this.originX) / this.size), Math.floor((wy - this.originY) / this.size)];
  }

  cellCentre(cx: number, cy: number): [number, number] {
    return [this.originX + (cx + 0.5) * this.size, this.originY + (cy + 0.5) * this.size];
  }

  hasWall(floor: string, side: Side): boolean {
    return this.walled.has(`${floor}/${side}`);
  }

  /** The floor next to a placed floor on a side, if any. */
  neighbour(floor: PlacedFloor, side: Side): PlacedFloor | undefined {
    const [dx, dy] = STEP[side];
    return this.cell(floor.x + dx, floor.y + dy);
  }

  /**
   * Empty cells next to a floor through a side without a wall: where addFloor can put a floor. Every
   * floor around the cell becomes its neighbour, so the new floor joins the floors the user sees around it.
   * O(floors): each floor looks at its four sides once.
   */
  ghosts(): Ghost[] {
    const found = new Map<string, Ghost>();
    for (const floor of this.placed) {
      for (const side of SIDES) {
        if (this.hasWall(floor.name, side)) continue;
        const [dx, dy] = STEP[side];
        const gx = floor.x + dx;
        const gy = floor.y + dy;
        if (this.cell(gx, gy) !== undefined) continue;
        const k = key(gx, gy);
        let ghost = found.get(k);
        if (ghost === undefined) {
          const [centreX, centreY] = this.cellCentre(gx, gy);
          ghost = { x: gx, y: gy, centreX, centreY, neighbours: {} };
          found.set(k, ghost);
        }
        ghost.neighbours[OPPOSITE[side]] = floor.name;
      }
    }
    return [...found.values()];
  }

  /** `base` + the first number that names nothing yet (table1, table2, ...): always numbered, so a type
   * whose lower-cased name is a keyword (`box`) still makes an identifier. */
  fresh(base: string, reserved: ReadonlySet<string> = new Set()): string {
    const stem = identifier(base);
    for (let i = 1; ; i += 1) {
      const name = `${stem}${i}`;
      if (!this.names.has(name) && !reserved.has(name)) return name;
    }
  }

  /**
   * A name for a new floor of a graph room: F_x_y after its cell when free (and not negative), else F1, F2...
   * `reserved` holds the names already given to other ghosts of the same drawing, so no two ghosts share one.
   */
  freshFloor(ghost: Ghost, reserved: ReadonlySet<string> = new Set()): string {
    const byCell = `F_${ghost.x}_${ghost.y}`;
    if (ghost.x >= 0 && ghost.y >= 0 && !this.names.has(byCell) && !reserved.has(byCell)) return byCell;
    return this.fresh("F", reserved);
  }

  /** A name for a new wall: W_FLOOR_SIDE as in the design note, numbered when taken. */
  freshWall(floor: string, side: Side): string {
    const name = identifier(`W_${floor}_${side}`);
    return this.names.has(name) ? this.fresh(`${name}_`) : name;
  }
}

/** A DSL identifier: anything but letters, digits and _ dropped, never starting with a digit. */
export function identifier(base: string): string {
  const cleaned = base.replace(/[^A-Za-z0-9_]/g, "");
  const name = cleaned === "" ? "element" : cleaned;
  return /^[0-9]/.test(name) ? `_${name}` : name;
}
