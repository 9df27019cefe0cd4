// SPDX-License-Identifier: EPL-2.0
// What the page gets from its server (`/config.json`, written by rei.view.config) and from the router
// (docs/protocol.md). The page needs nothing else.

export type Category = "FLOOR" | "WALL" | "STATIC" | "DYNAMIC" | "HUMAN";

/** One body of world.json (docs/artifacts.md); pose is the body's centre [x, y, z, yaw]. */
export interface WorldObject {
  readonly name: string;
  readonly category: Category;
  readonly type: string;
  readonly shape: "BOX" | "CYLINDER" | "MESH" | "POLYGON";
  readonly size: readonly number[];
  readonly pose: readonly number[];
  readonly colour?: readonly number[];
  /** A POLYGON object's outline about its pose (concave or not); absent for every other shape. */
  readonly footprint?: RobotFootprint;
}

/** A robot's outline on the floor in its own frame (x forward, y left), as world.json gives a robot read from a
 * URDF or xacro description (docs/artifacts.md; contract/vocabulary.json footprints). */
export type RobotFootprint =
  | { readonly type: "polygon"; readonly points: readonly (readonly number[])[] }
  | { readonly type: "circle"; readonly x: number; readonly y: number; readonly radius: number };

export interface World {
  readonly bounds: readonly number[];
  readonly objects: readonly WorldObject[];
  readonly robot: {
    readonly name: string;
    readonly size: readonly number[];
    /** Absent for a box robot, whose footprint is its size rectangle centred on its pose. */
    readonly footprint?: RobotFootprint;
    readonly lidar?: { readonly beams: number; readonly rangeMin: number; readonly rangeMax: number };
  } | null;
}

/** A room from an occupancy map: the map as a PNG (data URI; its first row is the top) over `extent`
 * [xmin, ymin, xmax, ymax] in metres (rei.maps.map_picture). */
export interface Occupancy {
  readonly png: string;
  readonly extent: readonly number[];
}

/** A human's or dynamic object's Catmull-Rom trajectory, sampled by the server. */
export interface PathSpec {
  readonly name: string;
  readonly category: string;
  readonly points: readonly (readonly [number, number])[];
}

export interface Goal {
  readonly index: number;
  readonly x: number;
  readonly y: number;
  readonly tolerance: number;
  readonly floor: string;
}

/** Credentials for a router that authenticates (a later issue adds roles); null means anonymous. */
export interface RouterAuth {
  readonly authid: string;
  readonly method: "ticket" | "wampcra";
  readonly secret: string;
}

export interface ViewConfig {
  readonly format: "rei-view/1";
  readonly router: { readonly url: string; readonly realm: string; readonly auth: RouterAuth | null };
  readonly run_id: string;
  readonly topics: { readonly state: string; readonly mission: string; readonly signal: string };
  readonly world: World | null;
  /** The map drawn under the floors of a room from an occupancy map; null for every other room. */
  readonly occupancy: Occupancy | null;
  readonly paths: readonly PathSpec[];
  readonly mission: { readonly name: string; readonly goals: readonly Goal[] } | null;
  readonly utilities: Readonly<Record<string, number>>;
  readonly colours: Readonly<Record<string, string>>;
  /** Each fault window's edge as a mission event (FAULT_LASER_BLACKOUT_BEGIN): the fault it names, whether it
   * begins the window. Absent from a server older than fault windows. */
  readonly faults?: Readonly<Record<string, { readonly fault: string; readonly begin: boolean }>>;
  /** Where the page says it is subscribed (POST), so `rei run --view` can wait for it; null: nowhere. */
  readonly hello: string | null;
}

export async function loadConfig(url = "config.json"): Promise<ViewConfig> {
  const response = await fetch(url, { cache: "no-store" });
  if (!response.ok) {
    throw new Error(`${url}: HTTP ${response.status}`);
  }
  const config = (await response.json()) as ViewConfig;
  if (config.format !== "rei-view/1") {
    throw new Error(`${url}: unknown format ${String(config.format)}`);
  }
  return config;
}

// -- wire messages (docs/protocol.md) ----------------------------------------------------------------------

export interface MovingObject {
  readonly name: string;
  readonly type: string;
  readonly pose: readonly number[];
}

export interface StateMessage {
  readonly seq: number;
  readonly t: number;
  readonly full?: boolean;
  readonly objects: readonly MovingObject[];
  readonly robot: {
    readonly name: string;
    readonly pose: readonly number[];
    readonly odom?: readonly number[];
    readonly laser_min?: number;
    readonly laser_ranges?: readonly number[];
    readonly nav_state?: string;
  };
}

export type MissionEvent = "BEGIN" | "TASK_START" | "TASK_SUCCESS" | "TASK_FAIL" | "END";

export interface MissionMessage {
  readonly seq: number;
  readonly t: number;
  readonly event: MissionEvent;
  readonly task_index: number;
  readonly goal: readonly number[] | null;
  readonly reason?: string;
}

export interface SignalMessage {
  readonly seq: number;
  readonly t: number;
  readonly signal: string;
  readonly subject: string;
  readonly object: string;
  readonly distance: number;
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

function hasSeqAndTime(value: unknown): value is { seq: number; t: number } & Record<string, unknown> {
  return isRecord(value) && Number.isInteger(value["seq"]) && typeof value["t"] === "number";
}

/** Shape checks at the door: a malformed message is counted and dropped, never drawn half. */
export function asState(value: unknown): StateMessage | null {
  if (!hasSeqAndTime(value) || !Array.isArray(value["objects"])) return null;
  const robot = value["robot"];
  if (!isRecord(robot) || !Array.isArray(robot["pose"]) || robot["pose"].length < 4) return null;
  return value as unknown as StateMessage;
}

export function asMission(value: unknown): MissionMessage | null {
  if (!hasSeqAndTime(value) || typeof value["event"] !== "string" || !Number.isInteger(value["task_index"])) {
    return null;
  }
  return value as unknown as MissionMessage;
}

export function asSignal(value: unknown): SignalMessage | null {
  if (!hasSeqAndTime(value) || typeof value["signal"] !== "string") return null;
  return value as unknown as SignalMessage;
}
