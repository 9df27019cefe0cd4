// SPDX-License-Identifier: EPL-2.0
// Walls, furniture, the robot, humans and moving objects with their trajectories, and the mission's goals. These
// are few (tens, not thousands), so they are redrawn whole on every change. Each element is one <g> (or
// <rect>) carrying data-kind and data-name (goals: data-index), which is what the page's one pointer listener
// and the browser tests look for. Footprints are the catalogue's, turned by yaw like the live view's.
import { HUMAN, ROBOT_TRUE, WALL } from "../../draw/colours";
import { boxCorners, placed, robotOutline } from "../../geometry";
import { goalKey, nameKey } from "../model";
import type { RoomIndex } from "../room";
import { points, r, svg, Y } from "../svg";
import type { Footprint, Item, Mover } from "../types";
import { trajectoryPath } from "./spline";

export const GOAL = "#1f77b4";
/** A type without a colour. */
export const OBJECT_FALLBACK = "#9a9a9a";
const ROBOT_SIZE: Footprint = { type: "robot", shape: "box", sizeX: 0.3, sizeY: 0.3, height: 0.2, colour: null };
const HUMAN_SIZE: Footprint = { type: "Human", shape: "cylinder", sizeX: 0.5, sizeY: 0.5, height: 1.7, colour: null };

export type Registry = Map<string, SVGElement>;

const rad = (degrees: number): number => (degrees * Math.PI) / 180;

/** A footprint's outline: a described robot's own (polygon or circle, turned by yaw about the robot's origin as
 * the monitor does), a disc for a cylinder, else the box turned by yaw (degrees). */
export function outline(parent: Element, x: number, y: number, footprint: Footprint, yawDegrees: number,
                        attrs: Record<string, string | number>): SVGElement {
  const own = robotOutline(footprint.outline ?? undefined);
  if (own?.type === "circle") {
    const [[cx, cy] = [x, y]] = placed([[own.x, own.y]], x, y, rad(yawDegrees));
    return svg("circle", { cx: r(cx), cy: r(Y(cy)), r: r(own.radius), "data-outline": "circle", ...attrs }, parent);
  }
  if (own?.type === "polygon") {
    return svg("polygon", { points: points(placed(own.points, x, y, rad(yawDegrees))), "data-outline": "polygon",
      ...attrs }, parent);
  }
  if (footprint.shape === "cylinder") {
    return svg("circle", { cx: r(x), cy: r(Y(y)), r: r(footprint.sizeX / 2), ...attrs }, parent);
  }
  return svg("polygon", { points: points(boxCorners(x, y, footprint.sizeX, footprint.sizeY, rad(yawDegrees))),
    ...attrs }, parent);
}

export function drawWalls(layer: SVGGElement, index: RoomIndex, registry: Registry): void {
  for (const wall of index.diagram.room?.walls ?? []) {
    const rect = svg("rect", {
      x: r(wall.x - wall.sizeX / 2), y: r(Y(wall.y + wall.sizeY / 2)), width: r(wall.sizeX), height: r(wall.sizeY),
      fill: WALL, class: "wall", "data-kind": "wall", "data-name": wall.name,
    }, layer);
    registry.set(nameKey(wall.name), rect);
  }
}

export function drawObjects(layer: SVGGElement, labels: SVGGElement, items: readonly Item[],
                            registry: Registry): void {
  for (const item of items) {
    if (item.x === null || item.y === null) continue;
    const footprint = item.footprint ?? { ...ROBOT_SIZE, type: "?", sizeX: 0.5, sizeY: 0.5 };
    const group = svg("g", { class: "object", "data-kind": "object", "data-name": item.name,
      "data-floor": item.floor, "data-yaw": item.yaw }, layer);
    outline(group, item.x, item.y, footprint, item.yaw, { fill: footprint.colour ?? OBJECT_FALLBACK,
      "fill-opacity": 0.85, stroke: "#333" });
    if (footprint.shape === "box") frontMark(group, item.x, item.y, footprint.sizeX, footprint.sizeY, item.yaw);
    registry.set(nameKey(item.name), group);
    label(labels, item.x, item.y, item.name, "object-name");
  }
}

/** A small notch on the +x face: without it a square footprint (Box, Chair) looks the same at any yaw. */
function frontMark(parent: Element, x: number, y: number, sx: number, sy: number, yawDegrees: number): void {
  const a = rad(yawDegrees);
  const c = Math.cos(a);
  const s = Math.sin(a);
  const depth = Math.min(sx, sy) * 0.18;
  const along = (dx: number, dy: number): [number, number] => [x + dx * c - dy * s, y + dx * s + dy * c];
  svg("polygon", { points: points([along(sx / 2, -depth), along(sx / 2 - depth, 0), along(sx / 2, depth)]),
    fill: "#222", "fill-opacity": 0.45, class: "front" }, parent);
}

/** The robot: blue body with a white heading arrow, unlike any furniture. */
export function drawRobot(layer: SVGGElement, labels: SVGGElement, robot: Item | null, registry: Registry): void {
  if (robot === null || robot.x === null || robot.y === null) return;
  const footprint = robot.footprint ?? ROBOT_SIZE;
  const group = svg("g", { class: "robot", "data-kind": "robot", "data-name": robot.name, "data-floor": robot.floor,
    "data-yaw": robot.yaw }, layer);
  const span = robotSpan(footprint);
  // a robot is small (0.3 m); a halo makes it findable and easier to grab
  svg("circle", { cx: r(robot.x), cy: r(Y(robot.y)), r: r(span.reach * 1.2),
    fill: ROBOT_TRUE, "fill-opacity": 0.12, stroke: ROBOT_TRUE, "stroke-dasharray": "3 2", class: "halo" }, group);
  outline(group, robot.x, robot.y, footprint, robot.yaw, { fill: ROBOT_TRUE, stroke: "#0d1d4d" });
  const a = rad(robot.yaw);
  const len = span.size * 0.95;
  const tip: [number, number] = [robot.x + Math.cos(a) * len, robot.y + Math.sin(a) * len];
  svg("line", { x1: r(robot.x), y1: r(Y(robot.y)), x2: r(tip[0]), y2: r(Y(tip[1])), stroke: "#fff",
    "stroke-width": 2, class: "heading" }, group);
  const head = len * 0.35;
  const left: [number, number] = [tip[0] - Math.cos(a - 0.5) * head, tip[1] - Math.sin(a - 0.5) * head];
  const right: [number, number] = [tip[0] - Math.cos(a + 0.5) * head, tip[1] - Math.sin(a + 0.5) * head];
  svg("polygon", { points: points([tip, left, right]), fill: "#fff", stroke: ROBOT_TRUE, class: "heading" }, group);
  registry.set(nameKey(robot.name), group);
  label(labels, robot.x, robot.y - span.size * 0.9, robot.name, "robot-name");
}

/** How far the robot's body reaches from its origin, and its size for the heading arrow and the label: the box's
 * for a box robot, the outline's for a described one (its catalogue sizes are the metamodel's defaults). */
function robotSpan(footprint: Footprint): { reach: number; size: number } {
  const own = robotOutline(footprint.outline ?? undefined);
  if (own === null) {
    return { reach: Math.hypot(footprint.sizeX, footprint.sizeY) / 2,
      size: Math.max(footprint.sizeX, footprint.sizeY) };
  }
  const reach = own.type === "circle" ? Math.hypot(own.x, own.y) + own.radius
    : Math.max(...own.points.map(([px, py]) => Math.hypot(px, py)));
  return { reach, size: reach * Math.SQRT2 };
}

/**
 * A human (or moving object) and its trajectory in one <g>, so that a click on the path selects it too: the
 * spline the simulator follows, each control point with its time, and the body at the first point.
 */
export function drawMovers(layer: SVGGElement, labels: SVGGElement, movers: readonly Mover[],
                           registry: Registry): void {
  for (const mover of movers) {
    const placedPoints = mover.points.flatMap((p) =>
      (p.x === null || p.y === null ? [] : [{ x: p.x, y: p.y, t: p.seconds }]));
    const human = mover.kind === "human";
    const colour = human ? HUMAN : mover.footprint?.colour ?? OBJECT_FALLBACK;
    const group = svg("g", { class: `mover ${mover.kind}`, "data-kind": mover.kind, "data-name": mover.name }, layer);
    registry.set(nameKey(mover.name), group);
    if (placedPoints.length === 0) continue;
    svg("path", { d: trajectoryPath(placedPoints, mover.loop), fill: "none", stroke: colour, "stroke-width": 2.5,
      "stroke-dasharray": "6 4", "stroke-opacity": 0.75, class: "trajectory" }, group);
    // a wide invisible stroke: the dashed path alone is hard to hit
    svg("path", { d: trajectoryPath(placedPoints, mover.loop), fill: "none", stroke: "transparent",
      "stroke-width": 12, class: "hit" }, group);
    const footprint = mover.footprint ?? HUMAN_SIZE;
    const body = Math.max(footprint.sizeX, footprint.sizeY) / 2;
    placedPoints.forEach((p, i) => {
      if (i > 0) {
        svg("circle", { cx: r(p.x), cy: r(Y(p.y)), r: 0.07, fill: "#fff", stroke: colour, class: "point" }, group);
      }
      // the first point's time goes beside the body, not under it
      timeLabel(labels, p.x + (i === 0 ? body * 0.7 : 0), p.y - (i === 0 ? body * 0.7 : 0), p.t, i);
    });
    const first = placedPoints[0];
    if (first === undefined) continue;
    outline(group, first.x, first.y, footprint, 0, { fill: colour, "fill-opacity": 0.85, stroke: "#5a2f08",
      class: "body" });
    label(labels, first.x, first.y + footprint.sizeY / 2 + 0.08, mover.name, "mover-name");
  }
}

export function timeLabel(labels: SVGGElement, x: number, y: number, seconds: number, i: number): void {
  const text = svg("text", { x: r(x + 0.1), y: r(Y(y - 0.1)), class: "time", "data-point": i }, labels);
  text.textContent = `${formatSeconds(seconds)} s`;
}

export function formatSeconds(seconds: number): string {
  return Number.isInteger(seconds) ? String(seconds) : String(Math.round(seconds * 100) / 100);
}

/**
 * The mission's goals as numbered markers (1 is the first goal), joined in order by a dotted line that starts
 * at the robot. Goals on one floor are fanned out a little so that each marker can be seen and clicked.
 */
export function drawGoals(layer: SVGGElement, line: SVGGElement, index: RoomIndex, registry: Registry): void {
  const mission = index.diagram.mission;
  if (mission === null) return;
  const radius = Math.min(0.2, index.size * 0.2);
  const perFloor = new Map<string, number>();
  const route: [number, number][] = [];
  const robot = index.diagram.robot;
  if (robot !== null && robot.x !== null && robot.y !== null) route.push([robot.x, robot.y]);
  // a goal on the robot's floor (a round trip) or on furniture (an error to see) moves aside, or it would be hidden
  if (robot !== null && robot.floor !== null) perFloor.set(robot.floor, 1);
  for (const item of index.diagram.objects) if (item.floor !== null) perFloor.set(item.floor, 1);
  for (const goal of mission.goals) {
    if (goal.x === null || goal.y === null) continue;
    const seen = perFloor.get(goal.floor ?? "") ?? 0;
    perFloor.set(goal.floor ?? "", seen + 1);
    const angle = (seen * Math.PI) / 3 + Math.PI / 4;
    const shift = seen === 0 ? 0 : Math.max(radius * 1.6, index.size * 0.33);
    const x = goal.x + Math.cos(angle) * shift;
    const y = goal.y + Math.sin(angle) * shift;
    route.push([x, y]);
    const group = svg("g", { class: "goal", "data-kind": "goal", "data-index": goal.index,
      "data-floor": goal.floor ?? "" }, layer);
    svg("circle", { cx: r(x), cy: r(Y(y)), r: r(radius), fill: "#fff", stroke: GOAL, "stroke-width": 2 }, group);
    const text = svg("text", { x: r(x), y: r(Y(y)), "font-size": r(radius * 1.2), "text-anchor": "middle",
      "dominant-baseline": "central", fill: GOAL, class: "goal-number" }, group);
    text.textContent = String(mission.goals.indexOf(goal) + 1);
    registry.set(goalKey(goal.index), group);
  }
  if (route.length > 1) {
    svg("polyline", { points: points(route), fill: "none", stroke: GOAL, "stroke-width": 1.5,
      "stroke-dasharray": "2 4", class: "goal-route" }, line);
  }
}

/** A name in the labels group, whose font size follows the zoom so it stays readable. */
export function label(labels: SVGGElement, x: number, y: number, text: string, className: string): SVGTextElement {
  const element = svg("text", { x: r(x), y: r(Y(y)), "text-anchor": "middle", "dominant-baseline": "central",
    class: className }, labels);
  element.textContent = text;
  return element;
}
