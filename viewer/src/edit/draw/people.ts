// SPDX-License-Identifier: EPL-2.0
// People who see the robot (issue #38): a routed person's or a group's route as straight legs between its stops
// (the pedestrian model walks between them; the editor shows the order, not the exact way), each stop numbered
// with its wait; a crowd's two areas of floors, from (green) and to (red), and an arrow from one to the other.
// Each is one <g> with data-kind and data-name, as every other element, so it is selected by a click.
import { HUMAN } from "../../draw/colours";
import type { CrowdDraft, RouteDraft } from "../model";
import { nameKey } from "../model";
import type { RoomIndex } from "../room";
import { points, r, svg, Y } from "../svg";
import type { Area, CrowdAreas, GroupRoute, Mover, RouteStop } from "../types";
import type { Registry } from "./items";
import { formatSeconds, label, outline } from "./items";
import { DRAFT } from "./overlay";

export const CROWD_FROM = "#2e7d32";
export const CROWD_TO = "#c62828";
export const GROUP = "#8e44ad";
const BODY = { type: "Human", shape: "cylinder", sizeX: 0.5, sizeY: 0.5, height: 1.7, colour: null } as const;

interface Placed {
  x: number;
  y: number;
  wait: number;
  floor: string;
}

function placedStops(stops: readonly RouteStop[]): Placed[] {
  return stops.flatMap((s) => (s.x === null || s.y === null || s.floor === null ? []
    : [{ x: s.x, y: s.y, wait: s.waitSeconds, floor: s.floor }]));
}

/** The legs, the numbered stop markers and their waits; the body on the first stop. */
function drawStops(group: SVGGElement, labels: SVGGElement, index: RoomIndex, stops: readonly Placed[], loop: boolean,
                   colour: string, draft: boolean): void {
  if (stops.length === 0) return;
  const line = stops.map((s): [number, number] => [s.x, s.y]);
  const first = stops[0];
  if (loop && stops.length > 2 && first !== undefined) line.push([first.x, first.y]);
  if (line.length > 1) {
    svg("polyline", { points: points(line), fill: "none", stroke: colour, "stroke-width": 2.5,
      "stroke-dasharray": draft ? "5 3" : "8 3 2 3", "stroke-opacity": 0.8, class: draft ? "draft-path" : "route",
      "pointer-events": draft ? "none" : null }, group);
    if (!draft) {
      svg("polyline", { points: points(line), fill: "none", stroke: "transparent", "stroke-width": 12, class: "hit" },
        group);
    }
  }
  const radius = Math.min(0.18, index.size * 0.18);
  stops.forEach((stop, i) => {
    const marker = svg("g", { class: draft ? "draft-stop" : "stop", "data-stop": i, "data-floor": stop.floor,
      "pointer-events": draft ? "none" : null }, group);
    svg("circle", { cx: r(stop.x), cy: r(Y(stop.y)), r: r(radius), fill: "#fff", stroke: colour,
      "stroke-width": 2 }, marker);
    const number = svg("text", { x: r(stop.x), y: r(Y(stop.y)), "font-size": r(radius * 1.1), "text-anchor": "middle",
      "dominant-baseline": "central", fill: colour, class: "stop-number" }, marker);
    number.textContent = String(i + 1);
    if (stop.wait > 0) {
      const wait = svg("text", { x: r(stop.x + radius * 1.2), y: r(Y(stop.y - radius * 1.2)),
        class: draft ? "wait draft" : "wait", "data-stop": i }, labels);
      wait.textContent = `wait ${formatSeconds(stop.wait)} s`;
    }
  });
}

/** A person on a route: its route, and its body on the first stop (where it stands when the run starts). */
export function drawRoutedHuman(layer: SVGGElement, labels: SVGGElement, index: RoomIndex, mover: Mover,
                                registry: Registry): void {
  const group = svg("g", { class: "mover human routed", "data-kind": "human", "data-name": mover.name,
    "data-behaviour": mover.route?.behaviour ?? "" }, layer);
  registry.set(nameKey(mover.name), group);
  const stops = placedStops(mover.route?.stops ?? []);
  const first = stops[0];
  const footprint = mover.footprint ?? BODY;
  // the body under the stops' markers: the first stop's number stays readable
  if (first !== undefined) {
    outline(group, first.x, first.y, footprint, 0, { fill: HUMAN, "fill-opacity": 0.85, stroke: "#5a2f08",
      class: "body" });
  }
  drawStops(group, labels, index, stops, mover.loop, HUMAN, false);
  if (first === undefined) return;
  label(labels, first.x, first.y + footprint.sizeY / 2 + 0.08, `${mover.name} (${mover.route?.behaviour ?? ""})`,
    "mover-name");
}

/** A group: its leader's route, and the group's size beside the first stop. */
export function drawGroup(layer: SVGGElement, labels: SVGGElement, index: RoomIndex, group: GroupRoute,
                          registry: Registry): void {
  const element = svg("g", { class: "people group", "data-kind": "group", "data-name": group.name }, layer);
  registry.set(nameKey(group.name), element);
  const stops = placedStops(group.route?.stops ?? []);
  const first = stops[0];
  const footprint = group.footprint ?? BODY;
  if (first !== undefined) {
    outline(element, first.x, first.y, footprint, 0, { fill: GROUP, "fill-opacity": 0.8, stroke: "#3d1a4d",
      class: "body" });
  }
  drawStops(element, labels, index, stops, group.loop, GROUP, false);
  if (first === undefined) return;
  label(labels, first.x, first.y + footprint.sizeY / 2 + 0.08, `${group.name} ×${group.count}`, "mover-name");
}

type Cell = { x: number; y: number };

function placedArea(area: readonly Area[]): (Cell & { floor: string })[] {
  return area.flatMap((a) => (a.x === null || a.y === null || a.floor === null ? []
    : [{ x: a.x, y: a.y, floor: a.floor }]));
}

const centroid = (cells: readonly Cell[]): [number, number] =>
  [cells.reduce((s, c) => s + c.x, 0) / cells.length, cells.reduce((s, c) => s + c.y, 0) / cells.length];

/** One area: a tinted square on each of its floors. */
function drawArea(parent: SVGGElement, index: RoomIndex, cells: readonly (Cell & { floor: string })[], colour: string,
                  which: "from" | "to", draft: boolean): void {
  const s = index.size;
  const inset = s * 0.06;
  const area = svg("g", { class: `area ${which}${draft ? " draft" : ""}`, "data-area": which,
    "pointer-events": draft ? "none" : null }, parent);
  for (const cell of cells) {
    svg("rect", { x: r(cell.x - s / 2 + inset), y: r(Y(cell.y + s / 2 - inset)), width: r(s - 2 * inset),
      height: r(s - 2 * inset), fill: colour, "fill-opacity": draft ? 0.35 : 0.22, stroke: colour,
      "stroke-width": 1, "stroke-dasharray": draft ? "4 2" : null, "data-floor": cell.floor }, area);
  }
}

/** The arrow from the from area's centre to the to area's. */
function drawArrow(parent: SVGGElement, from: [number, number], to: [number, number], colour: string): void {
  const [x0, y0] = from;
  const [x1, y1] = to;
  const length = Math.hypot(x1 - x0, y1 - y0);
  if (length < 1e-6) return;
  svg("line", { x1: r(x0), y1: r(Y(y0)), x2: r(x1), y2: r(Y(y1)), stroke: colour, "stroke-width": 2,
    "stroke-dasharray": "6 4", class: "crowd-arrow", "pointer-events": "none" }, parent);
  const a = Math.atan2(y1 - y0, x1 - x0);
  const head = Math.min(0.45, length / 4);
  const left: [number, number] = [x1 - Math.cos(a - 0.45) * head, y1 - Math.sin(a - 0.45) * head];
  const right: [number, number] = [x1 - Math.cos(a + 0.45) * head, y1 - Math.sin(a + 0.45) * head];
  svg("polygon", { points: points([[x1, y1], left, right]), fill: colour, class: "crowd-arrow",
    "pointer-events": "none" }, parent);
}

export function drawCrowd(layer: SVGGElement, labels: SVGGElement, index: RoomIndex, crowd: CrowdAreas,
                          registry: Registry): void {
  const group = svg("g", { class: "people crowd", "data-kind": "crowd", "data-name": crowd.name,
    "data-count": crowd.count }, layer);
  registry.set(nameKey(crowd.name), group);
  const from = placedArea(crowd.from);
  const to = placedArea(crowd.to);
  drawArea(group, index, from, CROWD_FROM, "from", false);
  drawArea(group, index, to, CROWD_TO, "to", false);
  if (from.length === 0) return;
  const start = centroid(from);
  if (to.length > 0) drawArrow(group, start, centroid(to), HUMAN);
  const rate = crowd.rate === null ? "all at once" : `${formatSeconds(crowd.rate)}/s`;
  label(labels, start[0], start[1], `${crowd.name} ×${crowd.count}, ${rate}`, "crowd-name");
  if (to.length > 0) {
    const end = centroid(to);
    label(labels, end[0], end[1], `${crowd.name} → here`, "crowd-name to");
  }
}

/** The route being drawn: the same marks as a route, in the draft colour, not clickable. */
export function drawRouteDraft(layer: SVGGElement, labels: SVGGElement, index: RoomIndex, draft: RouteDraft): void {
  const stops = draft.stops.flatMap((s) => {
    const floor = index.floors.get(s.floor);
    return floor === undefined || floor.centreX === null || floor.centreY === null ? []
      : [{ x: floor.centreX, y: floor.centreY, wait: s.waitSeconds, floor: s.floor }];
  });
  const group = svg("g", { class: "route-draft" }, layer);
  drawStops(group, labels, index, stops, draft.loop, DRAFT, true);
}

/** The crowd being placed: both areas as chosen so far, the one being chosen outlined more strongly. */
export function drawCrowdDraft(layer: SVGGElement, index: RoomIndex, draft: CrowdDraft): void {
  const cells = (names: readonly string[]): (Cell & { floor: string })[] => names.flatMap((name) => {
    const floor = index.floors.get(name);
    return floor === undefined || floor.centreX === null || floor.centreY === null ? []
      : [{ x: floor.centreX, y: floor.centreY, floor: name }];
  });
  const group = svg("g", { class: "crowd-draft", "data-choosing": draft.area }, layer);
  const from = cells(draft.from);
  const to = cells(draft.to);
  drawArea(group, index, from, CROWD_FROM, "from", true);
  drawArea(group, index, to, CROWD_TO, "to", true);
  if (from.length > 0 && to.length > 0) drawArrow(group, centroid(from), centroid(to), DRAFT);
}

/** The rectangle being dragged over floors, in the colour of the area it chooses. */
export function drawAreaRectangle(layer: SVGGElement, a: [number, number], b: [number, number],
                                  which: "from" | "to"): void {
  const colour = which === "from" ? CROWD_FROM : CROWD_TO;
  svg("rect", { x: r(Math.min(a[0], b[0])), y: r(Y(Math.max(a[1], b[1]))), width: r(Math.abs(a[0] - b[0])),
    height: r(Math.abs(a[1] - b[1])), fill: colour, "fill-opacity": 0.12, stroke: colour, "stroke-width": 2,
    "stroke-dasharray": "6 3", class: "area-rectangle", "pointer-events": "none" }, layer);
}
