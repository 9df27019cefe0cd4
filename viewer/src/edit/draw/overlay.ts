// SPDX-License-Identifier: EPL-2.0
// What is drawn over the diagram for the current gesture: the add-wall buttons of a selected graph floor, the
// footprint being dragged, and the trajectory being drawn. Redrawn on every gesture step, so it is kept tiny.
import type { PathDraft } from "../model";
import type { PlacedFloor, RoomIndex } from "../room";
import { r, svg, Y } from "../svg";
import type { Footprint, Side } from "../types";
import { SIDES } from "../types";
import { formatSeconds, OBJECT_FALLBACK, outline } from "./items";
import { trajectoryPath } from "./spline";

export const DRAFT = "#7b1fa2";

/**
 * One button per free side of a selected floor of a graph room (no wall there and no floor next to it: the
 * engine refuses a wall on a side that leads to another floor). Each is a strip along the side.
 */
export function drawSideButtons(layer: SVGGElement, index: RoomIndex, floor: PlacedFloor): void {
  const s = index.size;
  const t = s * 0.16;
  const { centreX: x, centreY: y } = floor;
  const strips: Record<Side, [number, number, number, number]> = {
    top: [x - s / 2 + t, y + s / 2 - t, s - 2 * t, t],
    bottom: [x - s / 2 + t, y - s / 2, s - 2 * t, t],
    left: [x - s / 2, y - s / 2 + t, t, s - 2 * t],
    right: [x + s / 2 - t, y - s / 2 + t, t, s - 2 * t],
  };
  for (const side of SIDES) {
    if (index.hasWall(floor.name, side) || index.neighbour(floor, side) !== undefined) continue;
    const [bx, by, w, h] = strips[side];
    const button = svg("g", { class: "side-button", id: `wall-${side}`, "data-add-wall": side, "data-floor": floor.name },
      layer);
    svg("rect", { x: r(bx), y: r(Y(by + h)), width: r(w), height: r(h) }, button);
    const plus = svg("text", { x: r(bx + w / 2), y: r(Y(by + h / 2)), "text-anchor": "middle",
      "dominant-baseline": "central", "font-size": r(t * 0.9) }, button);
    plus.textContent = "+";
    svg("title", {}, button).textContent = `add a wall on the ${side} of ${floor.name}`;
  }
}

export function drawFloorOutline(layer: SVGGElement, index: RoomIndex, floor: PlacedFloor): void {
  const s = index.size;
  svg("rect", { x: r(floor.centreX - s / 2), y: r(Y(floor.centreY + s / 2)), width: r(s), height: r(s),
    class: "floor-outline", "pointer-events": "none" }, layer);
}

/** The dragged footprint: on the floor it would land on, or under the pointer (red) where a drop does nothing. */
export function drawDragPreview(layer: SVGGElement, at: [number, number], footprint: Footprint, yaw: number,
                                onFloor: boolean): void {
  outline(layer, at[0], at[1], footprint, yaw, {
    class: onFloor ? "drag-preview" : "drag-preview nowhere", "pointer-events": "none",
  });
}

/**
 * The trajectory being drawn: the spline so far, its points numbered and timed. A new moving object's is drawn
 * as moving objects are: in its type's colour, its outline at the first point.
 */
export function drawDraft(layer: SVGGElement, labels: SVGGElement, index: RoomIndex, draft: PathDraft): void {
  const placed = draft.points.flatMap((p) => {
    const floor = index.floors.get(p.floor);
    return floor === undefined || floor.centreX === null || floor.centreY === null ? []
      : [{ x: floor.centreX, y: floor.centreY, t: p.seconds }];
  });
  const first = placed[0];
  if (first === undefined) return;
  const colour = draft.footprint === null ? DRAFT : draft.footprint.colour ?? OBJECT_FALLBACK;
  svg("path", { d: trajectoryPath(placed, draft.loop), fill: "none", stroke: colour, "stroke-width": 2.5,
    "stroke-dasharray": "5 3", class: "draft-path", "pointer-events": "none" }, layer);
  if (draft.footprint !== null) {
    outline(layer, first.x, first.y, draft.footprint, 0, { fill: colour, "fill-opacity": 0.85, stroke: "#5a2f08",
      class: "draft-body", "pointer-events": "none" });
  }
  placed.forEach((p, i) => {
    svg("circle", { cx: r(p.x), cy: r(Y(p.y)), r: r(index.size * 0.12), fill: colour, class: "draft-point",
      "data-point": i, "pointer-events": "none" }, layer);
    const text = svg("text", { x: r(p.x + index.size * 0.15), y: r(Y(p.y - index.size * 0.15)), class: "time draft",
      "data-point": i }, labels);
    text.textContent = `${i + 1}: ${formatSeconds(p.t)} s`;
  });
}
