// SPDX-License-Identifier: EPL-2.0
// The JSON of the room editor's HTTP API, as docs/room-editor.md ("Protocol") specifies it. The Diagram records
// are bundles/org.rei.dsl.edit/.../diagram/Diagram.java written by Jackson: every component by name, nulls kept.
// Units: metres, seconds, degrees; x right, y up, origin at the room's bottom-left corner.
import type { RobotFootprint } from "../config";

export type RoomForm = "grid" | "map" | "graph" | "occupancy";
export type Side = "top" | "right" | "bottom" | "left";
export const SIDES: readonly Side[] = ["top", "right", "bottom", "left"];

export interface FloorCell {
  name: string;
  type: string;
  /** Cell indices of the layout; null for a floor the layout could not place (then also no centre). */
  x: number | null;
  y: number | null;
  centreX: number | null;
  centreY: number | null;
  /** A statement of the text (graph rooms); false when derived from `size C x R` or a map. */
  written: boolean;
}

export interface WallSide {
  name: string;
  type: string;
  floor: string;
  side: Side;
  /** Centre and size of the wall's axis-aligned box. */
  x: number;
  y: number;
  sizeX: number;
  sizeY: number;
  written: boolean;
}

export interface Room {
  name: string;
  form: RoomForm;
  floorSize: number;
  columns: number;
  rows: number;
  floors: FloorCell[];
  walls: WallSide[];
}

export interface Footprint {
  type: string;
  shape: "box" | "cylinder" | "polygon";
  sizeX: number;
  sizeY: number;
  height: number;
  colour: string | null;
  /** A robot type read from a URDF or xacro description: its file (relative to the case), arguments, lidar link. */
  description?: { file: string; args: Record<string, string>; lidar: string | null } | null;
  /** Its outline in the robot's frame as world.json's robot.footprint (the server reads it), or a polygon type's
   * polygon about the item's place (the engine sends it); null: draw the box. */
  outline?: RobotFootprint | null;
}

export interface Item {
  name: string;
  kind: "object" | "robot";
  floor: string | null;
  /** Degrees, counter-clockwise from +x. */
  yaw: number;
  /** The floor's centre; null when the floor is not placed. */
  x: number | null;
  y: number | null;
  footprint: Footprint | null;
}

export interface Waypoint {
  floor: string | null;
  seconds: number;
  x: number | null;
  y: number | null;
}

export interface Mover {
  name: string;
  kind: "human" | "dynamic";
  footprint: Footprint | null;
  points: Waypoint[];
  /** The trajectory's, or the route's: starts over after its last point or stop. */
  loop: boolean;
  /** A person who sees the robot walks a route instead of a trajectory (no points then); null otherwise. */
  route: Route | null;
}

export interface RouteStop {
  floor: string | null;
  waitSeconds: number;
  x: number | null;
  y: number | null;
}

/** A route of floors (docs/language.md): stops in order, speed m/s, start s, behaviour as written (`avoids`...). */
export interface Route {
  stops: RouteStop[];
  speed: number;
  start: number;
  behaviour: string;
}

/** A floor of a crowd's area and its centre (null when the floor is not placed). */
export interface Area {
  floor: string | null;
  x: number | null;
  y: number | null;
}

/** A crowd: `count` people spread over the `from` floors who walk to the `to` floors, `rate` a second (null: all
 * at once). */
export interface CrowdAreas {
  name: string;
  count: number;
  footprint: Footprint | null;
  from: Area[];
  to: Area[];
  rate: number | null;
  speed: number;
  loop: boolean;
  behaviour: string;
}

/** A group: `count` people who walk their leader's route together. */
export interface GroupRoute {
  name: string;
  count: number;
  footprint: Footprint | null;
  route: Route | null;
  loop: boolean;
}

export interface Goal {
  /** Place in the mission's task list, from 0 (the operations' index). */
  index: number;
  floor: string | null;
  timeout: number | null;
  x: number | null;
  y: number | null;
}

export interface Mission {
  name: string;
  tolerance: number;
  taskTimeout: number;
  goals: Goal[];
}

export interface Monitor {
  close: number;
  collision: number;
  maxHumanCollisions: number;
}

export interface Diagram {
  testCase: string;
  room: Room | null;
  objects: Item[];
  robot: Item | null;
  movers: Mover[];
  mission: Mission | null;
  monitor: Monitor | null;
  /** Optional: an engine older than the page's has neither. */
  crowds?: CrowdAreas[];
  groups?: GroupRoute[];
}

export interface Issue {
  severity: "error" | "warning" | "info";
  message: string;
  line: number;
  column: number;
  offset: number;
  length: number;
  code: string | null;
  element: string | null;
  kind: string | null;
  index: number | null;
  /** Other elements the message is about; optional so that an engine without it still works. */
  related?: string[] | null;
}

export interface PaletteType {
  name: string;
  category: "object" | "dynamic" | "human" | "robot" | "floor" | "wall";
  shape: "box" | "cylinder" | "polygon";
  sizeX: number;
  sizeY: number;
  colour: string | null;
}

export interface Status {
  version: number;
  dirty: boolean;
  diskChanged: boolean;
  canUndo: boolean;
  canRedo: boolean;
}

/** A room from an occupancy map: the map the text names, as a PNG data URI whose first row is the top, over
 * `extent` [xmin, ymin, xmax, ymax], the map's `origin` [x, y] (metres). */
export interface Occupancy {
  png: string;
  extent: number[];
  origin: number[];
}

export interface State extends Status {
  file: string;
  text: string;
  diagram: Diagram;
  issues: Issue[];
  palette: PaletteType[];
  notice: string | null;
  /** Null unless the room is made from an occupancy map that can be read. */
  occupancy: Occupancy | null;
}

export interface PointSpec {
  floor: string;
  seconds: number;
}

/** A stop of a route: a floor and the seconds the person waits there (EditOperation.Stop). */
export interface StopSpec {
  floor: string;
  waitSeconds: number;
}

/** One EditOperation record (bundles/org.rei.dsl.edit/.../EditOperation.java), its kind in `op`. */
export type Operation =
  | { op: "moveObject"; name: string; floor: string }
  | { op: "rotateObject"; name: string; yawDegrees: number }
  | { op: "addObject"; name: string; type: string; floor: string }
  | { op: "deleteObject"; name: string }
  | { op: "addHuman"; name: string; type: string | null; points: PointSpec[]; loop: boolean }
  | { op: "addDynamic"; name: string; type: string; points: PointSpec[]; loop: boolean }
  | { op: "addFloor"; name: string; neighbours: Partial<Record<Side, string>> }
  | { op: "removeFloor"; name: string }
  | { op: "addWall"; name: string; floor: string; side: Side }
  | { op: "removeWall"; name: string }
  | { op: "setTrajectory"; name: string; points: PointSpec[]; loop: boolean }
  | { op: "setRoute"; name: string; stops: StopSpec[]; speed: number; start: number; loop: boolean; behaviour: string }
  | { op: "addCrowd"; name: string; type: string | null; count: number; from: string[]; to: string[];
      rate: number | null }
  | { op: "setCrowd"; name: string; count: number; from: string[]; to: string[]; rate: number | null }
  | { op: "addGoal"; floor: string; index: number; timeoutSeconds: number | null }
  | { op: "removeGoal"; index: number }
  | { op: "moveGoal"; from: number; to: number };
