// SPDX-License-Identifier: EPL-2.0
// World metres to canvas pixels (x right, y up in the world; y down on the canvas), and footprints.
import type { RobotFootprint, World, WorldObject } from "./config";

export type Bounds = readonly [number, number, number, number];

export class Transform {
  constructor(
    /** Pixels per metre. */
    readonly scale: number,
    /** Canvas pixel of world x = 0 and of world y = 0. */
    readonly ox: number,
    readonly oy: number,
  ) {}

  static fit(bounds: Bounds, width: number, height: number, pad = 24): Transform {
    const [xmin, ymin, xmax, ymax] = bounds;
    const w = Math.max(xmax - xmin, 1e-6);
    const h = Math.max(ymax - ymin, 1e-6);
    const scale = Math.max(1e-6, Math.min((width - 2 * pad) / w, (height - 2 * pad) / h));
    const ox = (width - w * scale) / 2 - xmin * scale;
    const oy = (height + h * scale) / 2 + ymin * scale;
    return new Transform(scale, ox, oy);
  }

  x(x: number): number {
    return this.ox + x * this.scale;
  }

  y(y: number): number {
    return this.oy - y * this.scale;
  }

  /** Canvas pixel back to world metres. */
  toWorld(px: number, py: number): [number, number] {
    return [(px - this.ox) / this.scale, (this.oy - py) / this.scale];
  }
}

/** The four corners of a box of size (sx, sy) centred at (x, y), turned by yaw. */
export function boxCorners(x: number, y: number, sx: number, sy: number, yaw: number): [number, number][] {
  const c = Math.cos(yaw);
  const s = Math.sin(yaw);
  const hx = sx / 2;
  const hy = sy / 2;
  return [[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]].map(
    ([dx = 0, dy = 0]) => [x + dx * c - dy * s, y + dx * s + dy * c] as [number, number]);
}

/** A robot's outline read from world.json: a circle, or a polygon of at least three vertices; null (draw the box)
 * for a box robot and for a footprint that does not read, as the report's map does. */
export type RobotOutline =
  | { readonly type: "polygon"; readonly points: readonly [number, number][] }
  | { readonly type: "circle"; readonly x: number; readonly y: number; readonly radius: number };

export function robotOutline(footprint: RobotFootprint | undefined): RobotOutline | null {
  if (typeof footprint !== "object" || footprint === null) return null;
  const finite = (v: unknown): v is number => typeof v === "number" && Number.isFinite(v);
  if (footprint.type === "circle") {
    const { x, y, radius } = footprint;
    return finite(x) && finite(y) && finite(radius) && radius > 0 ? { type: "circle", x, y, radius } : null;
  }
  if (footprint.type === "polygon" && Array.isArray(footprint.points) && footprint.points.length >= 3) {
    const points: [number, number][] = [];
    for (const point of footprint.points) {
      const [px, py] = Array.isArray(point) ? point : [];
      if (!finite(px) || !finite(py)) return null;
      points.push([px, py]);
    }
    return { type: "polygon", points };
  }
  return null;
}

/** Points of the robot's frame placed at pose (x, y, yaw): turned about the robot's origin, as the monitor does. */
export function placed(points: readonly (readonly [number, number])[], x: number, y: number,
                       yaw: number): [number, number][] {
  const c = Math.cos(yaw);
  const s = Math.sin(yaw);
  return points.map(([px, py]) => [x + px * c - py * s, y + px * s + py * c] as [number, number]);
}

/** A POLYGON object's outline in the world (its footprint placed at its pose and turned by its yaw); null for
 * every other body, and for a footprint that does not read (then its bounding box is drawn). */
export function objectOutline(body: WorldObject): [number, number][] | null {
  const own = body.shape === "POLYGON" ? robotOutline(body.footprint) : null;
  if (own === null || own.type !== "polygon") return null;
  const [x = 0, y = 0, , yaw = 0] = body.pose;
  return placed(own.points, x, y, yaw);
}

/** Whether world point (px, py) lies on the body's footprint (a turned box, a disc for a cylinder, a polygon). */
export function contains(body: WorldObject, px: number, py: number): boolean {
  const [x = 0, y = 0, , yaw = 0] = body.pose;
  const [sx = 0, sy = 0] = body.size;
  const dx = px - x;
  const dy = py - y;
  const own = objectOutline(body);
  if (own !== null) {  // even-odd crossings of a ray towards +x
    let inside = false;
    for (let i = 0, j = own.length - 1; i < own.length; j = i++) {
      const [xi = 0, yi = 0] = own[i] ?? [];
      const [xj = 0, yj = 0] = own[j] ?? [];
      if ((yi > py) !== (yj > py) && px < ((xj - xi) * (py - yi)) / (yj - yi) + xi) inside = !inside;
    }
    return inside;
  }
  if (body.shape === "CYLINDER") return Math.hypot(dx, dy) <= sx / 2;
  const c = Math.cos(-yaw);
  const s = Math.sin(-yaw);
  const lx = dx * c - dy * s;
  const ly = dx * s + dy * c;
  return Math.abs(lx) <= sx / 2 && Math.abs(ly) <= sy / 2;
}

/** The area to show: the room's bounds and every body, with a margin. */
export function worldBounds(world: World | null): Bounds {
  const box = [Infinity, Infinity, -Infinity, -Infinity];
  const grow = (x: number, y: number): void => {
    box[0] = Math.min(box[0] ?? x, x);
    box[1] = Math.min(box[1] ?? y, y);
    box[2] = Math.max(box[2] ?? x, x);
    box[3] = Math.max(box[3] ?? y, y);
  };
  if (world !== null) {
    const [bx0, by0, bx1, by1] = world.bounds;
    if (bx0 !== undefined && by0 !== undefined && bx1 !== undefined && by1 !== undefined) {
      grow(bx0, by0);
      grow(bx1, by1);
    }
    for (const body of world.objects) {
      const [x = 0, y = 0, , yaw = 0] = body.pose;
      const [sx = 0, sy = 0] = body.size;
      for (const [cx, cy] of boxCorners(x, y, sx, sy, yaw)) grow(cx, cy);
    }
  }
  const [xmin = 0, ymin = 0, xmax = 1, ymax = 1] = box;
  if (!Number.isFinite(xmin)) return [-0.3, -0.3, 1.3, 1.3];
  const margin = 0.3;
  return [xmin - margin, ymin - margin, xmax + margin, ymax + margin];
}
