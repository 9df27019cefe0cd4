// SPDX-License-Identifier: EPL-2.0
// Colours of the view; signal colours come from the server (rei.report.colours), so page and report agree.
import type { Zone } from "../model";

export const ROBOT_TRUE = "#1f3a93";
export const ROBOT_BELIEVED = "#e67e22";
export const HUMAN = "#b5651d";
/** The room as both the live view and the room editor draw it. */
export const FLOOR = "#efebe4";
export const FLOOR_EDGE = "#ddd6ca";
export const WALL = "#4a4a4a";
export const LASER = "rgba(214, 22, 106, 0.55)";
export const ZONE: Readonly<Record<Zone, string>> = { FAR: "#59a14f", CLOSE: "#f28e2b", COLLISION: "#e15759" };
export const TASK = { PENDING: "#9aa0a6", ACTIVE: "#1f77b4", SUCCEEDED: "#2ca02c", FAILED: "#d62728" } as const;

const FALLBACK = ["#1f77b4", "#ff7f0e", "#17becf", "#bcbd22", "#7f7f7f", "#8c564b"];

export function signalColour(colours: Readonly<Record<string, string>>, signal: string): string {
  const known = colours[signal];
  if (known !== undefined) return known;
  let hash = 0;
  for (let i = 0; i < signal.length; i += 1) hash = (hash * 31 + signal.charCodeAt(i)) >>> 0;
  return FALLBACK[hash % FALLBACK.length] ?? "#1f77b4";
}

/** A world.json colour [r, g, b, a] in 0..1 as CSS. */
export function cssColour(rgba: readonly number[] | undefined, fallback = "#999999"): string {
  if (rgba === undefined || rgba.length < 3) return fallback;
  const [r = 0, g = 0, b = 0] = rgba.map((c) => Math.max(0, Math.min(255, Math.round(c * 255))));
  return `rgb(${r},${g},${b})`;
}
