// SPDX-License-Identifier: EPL-2.0
// A trajectory's path as the simulator moves along it: the timed Catmull-Rom (cubic Hermite) spline of
// sim-adapter/src/rei/sim/spline.py (thesis 4.2.1), knot velocities from the control points' times, closed by
// a segment as long as the first one when it loops. Each Hermite segment is exactly a cubic Bezier with
// control points p0 + v0 h/3 and p1 - v1 h/3, so SVG draws the spline itself, not an approximation. Times that
// do not increase (the validator says so) fall back to straight lines, so the points still show.
import { r, Y } from "../svg";

export interface TimedPoint {
  x: number;
  y: number;
  t: number;
}

type P = readonly [number, number];

export function trajectoryPath(input: readonly TimedPoint[], loop: boolean): string {
  if (input.length === 0) return "";
  const polyline = (): string =>
    input.map((p, i) => `${i === 0 ? "M" : "L"}${r(p.x)} ${r(Y(p.y))}`).join(" ") + (loop ? " Z" : "");
  if (input.length === 1) return polyline();
  for (let i = 1; i < input.length; i += 1) {
    if (!((input[i]?.t ?? 0) > (input[i - 1]?.t ?? 0))) return polyline();
  }
  const pts: P[] = input.map((p) => [p.x, p.y]);
  const knots = input.map((p) => p.t);
  let closedLoop = loop;
  if (loop) {
    const first = pts[0] as P;
    const last = pts[pts.length - 1] as P;
    const closed = Math.hypot(first[0] - last[0], first[1] - last[1]) < 1e-9;
    if (closed && pts.length === 2) return polyline();
    if (!closed) {
      knots.push((knots[knots.length - 1] ?? 0) + (knots[1] ?? 0) - (knots[0] ?? 0));
      pts.push(first);
    }
  } else {
    closedLoop = false;
  }
  const n = pts.length;
  const slopes: P[] = [];
  for (let i = 0; i < n - 1; i += 1) {
    const a = pts[i] as P;
    const b = pts[i + 1] as P;
    const dt = (knots[i + 1] ?? 0) - (knots[i] ?? 0);
    slopes.push([(b[0] - a[0]) / dt, (b[1] - a[1]) / dt]);
  }
  const mean = (a: P, b: P): P => [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
  const v: P[] = pts.map(() => [0, 0]);
  for (let i = 1; i < n - 1; i += 1) v[i] = mean(slopes[i - 1] as P, slopes[i] as P);
  if (closedLoop) {
    const seam = mean(slopes[slopes.length - 1] as P, slopes[0] as P);
    v[0] = seam;
    v[n - 1] = seam;
  } else {
    v[0] = slopes[0] as P;
    v[n - 1] = slopes[slopes.length - 1] as P;
  }
  const start = pts[0] as P;
  let d = `M${r(start[0])} ${r(Y(start[1]))}`;
  for (let i = 0; i < n - 1; i += 1) {
    const h = (knots[i + 1] ?? 0) - (knots[i] ?? 0);
    const p0 = pts[i] as P;
    const p1 = pts[i + 1] as P;
    const v0 = v[i] as P;
    const v1 = v[i + 1] as P;
    const c1: P = [p0[0] + (v0[0] * h) / 3, p0[1] + (v0[1] * h) / 3];
    const c2: P = [p1[0] - (v1[0] * h) / 3, p1[1] - (v1[1] * h) / 3];
    d += ` C${r(c1[0])} ${r(Y(c1[1]))} ${r(c2[0])} ${r(Y(c2[1]))} ${r(p1[0])} ${r(Y(p1[1]))}`;
  }
  return d;
}
