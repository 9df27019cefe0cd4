// SPDX-License-Identifier: EPL-2.0
// The editor's own state around the server's State: what is selected, which tool is active, and which diagram
// elements the validation issues are on. Elements are found by name (names are unique in a test case); goals
// have no name and are found by their place in the mission.
import type { Footprint, Issue, PaletteType, PointSpec, StopSpec } from "./types";

export type Kind = "floor" | "wall" | "object" | "robot" | "human" | "dynamic" | "goal" | "crowd" | "group" | "ghost";
/** The kinds that can be selected (a ghost is clicked to add a floor, never selected). */
export const KINDS: ReadonlySet<string> = new Set(["floor", "wall", "object", "robot", "human", "dynamic", "goal",
  "crowd", "group"]);

export interface Selection {
  kind: Kind;
  /** The element's name; for a goal its index as a string. */
  name: string;
}

/**
 * A trajectory being drawn: an existing mover's (setTrajectory), a new human's (addHuman) or a new moving
 * object's (addDynamic).
 */
export interface PathDraft {
  name: string;
  isNew: boolean;
  kind: "human" | "dynamic";
  /** addHuman's type (null for the default Human) or addDynamic's (never null: the grammar requires it). */
  type: string | null;
  /** A new moving object's outline, drawn at the first point in its type's colour; null otherwise. */
  footprint: Footprint | null;
  points: PointSpec[];
  loop: boolean;
}

/** The route of a person who sees the robot being drawn: one setRoute on Finish (speed, start, behaviour kept). */
export interface RouteDraft {
  name: string;
  stops: StopSpec[];
  loop: boolean;
}

/**
 * A crowd being placed (addCrowd) or changed (setCrowd): its two areas of floors, the one clicks and rectangles
 * go to (`area`), its size and rate. One operation on Finish, so the whole placement is one undo step.
 */
export interface CrowdDraft {
  name: string;
  isNew: boolean;
  count: number;
  /** People a second; null: all set off at once. */
  rate: number | null;
  from: string[];
  to: string[];
  area: "from" | "to";
}

/** The active tool. Placing and adding a goal are one click each (Shift-click keeps the tool), like most editors. */
export type Tool =
  | { kind: "select" }
  | { kind: "place"; type: PaletteType }
  | { kind: "goal" }
  | { kind: "path"; draft: PathDraft }
  | { kind: "route"; draft: RouteDraft }
  | { kind: "crowd"; draft: CrowdDraft };

/** The key of a diagram element: `n:NAME`, or `g:INDEX` for a goal. */
export const nameKey = (name: string): string => `n:${name}`;
export const goalKey = (index: number): string => `g:${index}`;

export function selectionKey(selection: Selection): string {
  return selection.kind === "goal" ? goalKey(Number(selection.name)) : nameKey(selection.name);
}

/** The diagram elements an issue is about: its element (a goal: its marker) and the related names. */
export function issueKeys(issue: Issue): string[] {
  const keys: string[] = [];
  if (issue.kind === "goal" && issue.index !== null) keys.push(goalKey(issue.index));
  else if (issue.element !== null) keys.push(nameKey(issue.element));
  for (const name of issue.related ?? []) {
    const key = nameKey(name);
    if (!keys.includes(key)) keys.push(key);
  }
  return keys;
}

/** Issues by element key, in the order the engine gave them. O(issues). */
export function issuesByKey(issues: readonly Issue[]): Map<string, Issue[]> {
  const byKey = new Map<string, Issue[]>();
  for (const issue of issues) {
    for (const key of issueKeys(issue)) {
      const list = byKey.get(key);
      if (list === undefined) byKey.set(key, [issue]);
      else list.push(issue);
    }
  }
  return byKey;
}

/** Seconds to walk from one floor centre to the next at 1 m/s, in whole seconds (at least 1: times must grow). */
export function walkSeconds(distance: number): number {
  return Math.max(1, Math.ceil(distance - 1e-9));
}
