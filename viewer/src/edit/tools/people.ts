// SPDX-License-Identifier: EPL-2.0
// The route and crowd tools (issue #38): a routed person's stops drawn by clicking floors, and a crowd's two
// areas chosen by clicking floors or dragging a rectangle over them. Each draft becomes one operation on Finish
// (setRoute, addCrowd or setCrowd), so a whole drawing is one undo step, as a trajectory is.
import type { CrowdDraft, RouteDraft } from "../model";
import type { RoomIndex } from "../room";
import type { CrowdAreas, Mover, Operation, StopSpec } from "../types";

/** How many people a new crowd has, and how many set off a second: a small crowd the user then sizes. */
export const NEW_CROWD_COUNT = 4;
export const NEW_CROWD_RATE = 1;

/** The stops of a route as the operations write them (a stop on a floor the layout lost keeps no floor: dropped). */
export function stopsOf(mover: Mover): StopSpec[] {
  return (mover.route?.stops ?? []).flatMap((s) => (s.floor === null ? [] : [{ floor: s.floor,
    waitSeconds: s.waitSeconds }]));
}

/** Draw route: the clicks are the whole new route; Extend route: its stops first, the clicks appended. */
export function routeDraftOf(mover: Mover, extend: boolean): RouteDraft {
  return { name: mover.name, stops: extend ? stopsOf(mover) : [], loop: mover.loop };
}

/** A click on a floor appends a stop there without a wait; the same floor twice in a row is one stop. */
export function appendStop(draft: RouteDraft, floor: string): RouteDraft {
  if (draft.stops[draft.stops.length - 1]?.floor === floor) return draft;
  return { ...draft, stops: [...draft.stops, { floor, waitSeconds: 0 }] };
}

/** setRoute with the stops and loop given; the route's speed, start and behaviour stay as they are. */
export function routeOperation(mover: Mover, stops: StopSpec[], loop: boolean): Operation | null {
  const route = mover.route;
  if (route === null) return null;
  return { op: "setRoute", name: mover.name, stops, speed: route.speed, start: route.start, loop,
    behaviour: route.behaviour };
}

export function newCrowdDraft(index: RoomIndex): CrowdDraft {
  return { name: index.fresh("crowd"), isNew: true, count: NEW_CROWD_COUNT, rate: NEW_CROWD_RATE, from: [], to: [],
    area: "from" };
}

const floorsOf = (area: CrowdAreas["from"]): string[] => area.flatMap((a) => (a.floor === null ? [] : [a.floor]));

/** An existing crowd's areas to change; the clicks go to its from area first. */
export function crowdDraftOf(crowd: CrowdAreas): CrowdDraft {
  return { name: crowd.name, isNew: false, count: crowd.count, rate: crowd.rate, from: floorsOf(crowd.from),
    to: floorsOf(crowd.to), area: "from" };
}

/** A click: the floor joins the chosen area, or leaves it when it is in it already (a floor is in one area). */
export function toggleFloor(draft: CrowdDraft, floor: string): CrowdDraft {
  const area = draft[draft.area];
  const other = draft.area === "from" ? "to" : "from";
  const next = area.includes(floor) ? area.filter((f) => f !== floor) : [...area, floor];
  return { ...draft, [draft.area]: next, [other]: draft[other].filter((f) => f !== floor) };
}

/** A rectangle dragged over floors: they become the chosen area (a new rectangle replaces the area's floors). */
export function setArea(draft: CrowdDraft, floors: string[]): CrowdDraft {
  const other = draft.area === "from" ? "to" : "from";
  return { ...draft, [draft.area]: floors, [other]: draft[other].filter((f) => !floors.includes(f)) };
}

/** The floors whose centres lie in the rectangle between two world points, bottom row first, left to right. */
export function floorsIn(index: RoomIndex, a: [number, number], b: [number, number]): string[] {
  const [x0, x1] = [Math.min(a[0], b[0]), Math.max(a[0], b[0])];
  const [y0, y1] = [Math.min(a[1], b[1]), Math.max(a[1], b[1])];
  // the floors under the corners count too: a rectangle inside one floor picks that floor
  const [cx0, cy0] = index.cellAt(x0, y0);
  const [cx1, cy1] = index.cellAt(x1, y1);
  const names: string[] = [];
  for (let cy = cy0; cy <= cy1; cy += 1) {
    for (let cx = cx0; cx <= cx1; cx += 1) {
      const floor = index.cell(cx, cy);
      if (floor !== undefined) names.push(floor.name);
    }
  }
  return names;
}

/** What the page can say before sending (the engine says the rest, such as a floor that is not there). */
export function crowdProblem(draft: CrowdDraft): string | null {
  if (draft.from.length === 0) return "Choose the crowd's from area: click floors or drag a rectangle over them.";
  if (draft.to.length === 0) return "Choose the crowd's to area: press To, then click floors or drag a rectangle.";
  return null;
}

export function crowdOperation(draft: CrowdDraft): Operation {
  const { name, count, from, to, rate } = draft;
  return draft.isNew ? { op: "addCrowd", name, type: null, count, from, to, rate }
    : { op: "setCrowd", name, count, from, to, rate };
}
