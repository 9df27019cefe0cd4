// SPDX-License-Identifier: EPL-2.0
// The layer that never changes during a run: floors, walls, furniture (world.json footprints) and the
// humans' trajectories drawn faintly. Drawn once per resize into its own canvas, then copied each frame.
import type { Occupancy, PathSpec, World, WorldObject } from "../config";
import type { Transform } from "../geometry";
import { boxCorners, objectOutline } from "../geometry";
import { cssColour, FLOOR, FLOOR_EDGE, HUMAN, WALL } from "./colours";

const ORDER: Readonly<Record<string, number>> = { FLOOR: 0, STATIC: 1, DYNAMIC: 2, WALL: 3 };

function outline(ctx: CanvasRenderingContext2D, tf: Transform, body: WorldObject): void {
  const [x = 0, y = 0, , yaw = 0] = body.pose;
  const [sx = 0, sy = 0] = body.size;
  ctx.beginPath();
  const own = body.shape === "POLYGON" ? objectOutline(body) : null;
  if (own !== null) {  // furniture on a polygon: the polygon itself, not its bounding box
    for (const [cx, cy] of own) ctx.lineTo(tf.x(cx), tf.y(cy));
    ctx.closePath();
    return;
  }
  if (body.shape === "CYLINDER") {
    ctx.arc(tf.x(x), tf.y(y), (sx / 2) * tf.scale, 0, 2 * Math.PI);
    return;
  }
  for (const [cx, cy] of boxCorners(x, y, sx, sy, yaw)) ctx.lineTo(tf.x(cx), tf.y(cy));
  ctx.closePath();
}

/** A room from an occupancy map: the map's picture and where it lies. */
export interface MapPicture {
  readonly image: CanvasImageSource;
  readonly occupancy: Occupancy;
}

/** The map's picture over its extent, cells kept sharp; its first row is the top, as the canvas's y axis goes. */
function drawPicture(ctx: CanvasRenderingContext2D, tf: Transform, picture: MapPicture): void {
  const [x0 = 0, y0 = 0, x1 = 0, y1 = 0] = picture.occupancy.extent;
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(picture.image, tf.x(x0), tf.y(y1), (x1 - x0) * tf.scale, (y1 - y0) * tf.scale);
  ctx.imageSmoothingEnabled = true;
}

/** Draws in CSS pixels: the context's transform already scales to device pixels. Over a map's picture, floors
 * and walls are translucent so the map shows beneath them. */
export function drawRoom(ctx: CanvasRenderingContext2D, width: number, height: number, tf: Transform,
                         world: World | null, paths: readonly PathSpec[], picture: MapPicture | null = null): void {
  ctx.fillStyle = "#fbfbf8";
  ctx.fillRect(0, 0, width, height);
  if (picture !== null) drawPicture(ctx, tf, picture);
  const seeThrough = picture !== null;
  if (world !== null) {
    const bodies = world.objects.filter((b) => b.category in ORDER)
      .sort((a, b) => (ORDER[a.category] ?? 0) - (ORDER[b.category] ?? 0));
    for (const body of bodies) {
      outline(ctx, tf, body);
      if (body.category === "FLOOR") {
        ctx.fillStyle = FLOOR;
        ctx.strokeStyle = FLOOR_EDGE;
        ctx.lineWidth = 0.5;
      } else {
        ctx.fillStyle = body.category === "WALL" ? WALL : cssColour(body.colour);
        ctx.strokeStyle = "#333";
        ctx.lineWidth = 0.8;
      }
      ctx.globalAlpha = body.category === "STATIC" || body.category === "DYNAMIC" ? 0.85
        : !seeThrough ? 1 : body.category === "FLOOR" ? 0.45 : 0.3;
      ctx.fill();
      ctx.globalAlpha = 1;
      ctx.stroke();
      if (body.category === "STATIC") {
        ctx.fillStyle = "#222";
        ctx.font = "11px sans-serif";
        ctx.textAlign = "center";
        ctx.fillText(body.name, tf.x(body.pose[0] ?? 0), tf.y(body.pose[1] ?? 0) + 4);
      }
    }
  }
  ctx.strokeStyle = HUMAN;
  ctx.globalAlpha = 0.3;
  ctx.lineWidth = 2;
  ctx.setLineDash([5, 4]);
  for (const path of paths) {
    ctx.beginPath();
    for (const [x, y] of path.points) ctx.lineTo(tf.x(x), tf.y(y));
    ctx.stroke();
  }
  ctx.setLineDash([]);
  ctx.globalAlpha = 1;
  drawScale(ctx, width, height, tf);
}

/** Metre ticks along the bottom and left edges. */
function drawScale(ctx: CanvasRenderingContext2D, width: number, height: number, tf: Transform): void {
  const [x0, y0] = tf.toWorld(0, height);
  const [x1, y1] = tf.toWorld(width, 0);
  const step = tf.scale < 25 ? 5 : 1;
  ctx.fillStyle = "#777";
  ctx.font = "10px sans-serif";
  ctx.textAlign = "center";
  for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) {
    ctx.fillText(`${x} m`, tf.x(x), height - 4);
  }
  ctx.textAlign = "left";
  for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) ctx.fillText(`${y}`, 3, tf.y(y) + 3);
}
