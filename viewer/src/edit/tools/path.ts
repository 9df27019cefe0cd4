// SPDX-License-Identifier: EPL-2.0
// The trajectory tool: a draft of control points that becomes one setTrajectory (an existing human or moving
// object), one addHuman (a new human) or one addDynamic (a new moving object) when finished, so the whole path is
// a single undo step. A new point's
// time defaults to the previous one plus the walk at 1 m/s between the floor centres, in whole seconds: a
// plausible pace the user can then edit in the points list.
import type { PathDraft } from "../model";
import { walkSeconds } from "../model";
import type { RoomIndex } from "../room";
import type { Mover, Operation, PaletteType } from "../types";

/**
 * A path for an existing mover: drawn anew (Draw path: the clicks are the whole new path), or extended (its
 * points first, the clicks appended). Loop or once stays as it was until the user changes it.
 */
export function draftOf(mover: Mover, extend: boolean): PathDraft {
  const points = extend
    ? mover.points.flatMap((p) => (p.floor === null ? [] : [{ floor: p.floor, seconds: p.seconds }])) : [];
  return { name: mover.name, isNew: false, kind: mover.kind, type: null, footprint: null, loop: mover.loop, points };
}

export function newHumanDraft(index: RoomIndex, type: string): PathDraft {
  // the default catalogue's Human is what an untyped `human` is: leave the type out of the text
  return { name: index.fresh(type.toLowerCase()), isNew: true, kind: "human", type: type === "Human" ? null : type,
    footprint: null, points: [], loop: false };
}

/** A new moving object of a palette type (`dynamic cart1 : Cart trajectory [...]`): its type is always written. */
export function newDynamicDraft(index: RoomIndex, type: PaletteType): PathDraft {
  return { name: index.fresh(type.name.toLowerCase()), isNew: true, kind: "dynamic", type: type.name,
    footprint: { type: type.name, shape: type.shape, sizeX: type.sizeX, sizeY: type.sizeY, height: 0,
      colour: type.colour },
    points: [], loop: false };
}

/** Appends a point on `floor` at its default time. */
export function appendPoint(index: RoomIndex, draft: PathDraft, floor: string): PathDraft {
  const last = draft.points[draft.points.length - 1];
  if (last === undefined) return { ...draft, points: [{ floor, seconds: 0 }] };
  const a = index.floors.get(last.floor);
  const b = index.floors.get(floor);
  const distance = a?.centreX != null && a.centreY != null && b?.centreX != null && b.centreY != null
    ? Math.hypot(b.centreX - a.centreX, b.centreY - a.centreY) : index.size;
  return { ...draft, points: [...draft.points, { floor, seconds: last.seconds + walkSeconds(distance) }] };
}

export function finishOperation(draft: PathDraft): Operation {
  const { name, points, loop } = draft;
  if (!draft.isNew) return { op: "setTrajectory", name, points, loop };
  return draft.kind === "dynamic" && draft.type !== null
    ? { op: "addDynamic", name, type: draft.type, points, loop }
    : { op: "addHuman", name, type: draft.type, points, loop };
}
