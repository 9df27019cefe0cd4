// SPDX-License-Identifier: EPL-2.0
// The map: the room (drawn once), the marks that only grow (true path, signal markers: drawn incrementally)
// and, every frame, what moves: goals by task state, humans, the laser scan, the odometry ghost and the
// robot in the colour of its zone.
import type { MovingObject, StateMessage, ViewConfig } from "../config";
import { boxCorners, placed, robotOutline, type RobotOutline, Transform, worldBounds } from "../geometry";
import type { LiveModel, Zone } from "../model";
import { HUMAN, LASER, ROBOT_BELIEVED, ROBOT_TRUE, signalColour, TASK, ZONE } from "./colours";
import { Layer } from "./layer";
import { drawRoom, type MapPicture } from "./room";

interface Mover {
  x: number;
  y: number;
  radius: number;
}

/** What the last frame drew of the robot, in world units and canvas CSS pixels. */
export interface DrawnRobot {
  seq: number;
  t: number;
  pose: [number, number, number];
  odom: [number, number, number] | null;
  px: [number, number];
  zone: Zone;
}

const MAX_MARKERS = 4000;

export class MapView {
  readonly screen: Layer;
  transform = new Transform(1, 0, 0);
  private readonly room = new Layer();
  private readonly marks = new Layer();
  private trailDrawn = 0;
  private markersDrawn = 0;
  private readonly movers = new Map<string, Mover>();
  private readonly radii = new Map<string, number>();
  private readonly robotSize: [number, number];
  private readonly robotOutline: RobotOutline | null;
  private readonly lidarMax: number;
  private picture: MapPicture | null = null;

  constructor(canvas: HTMLCanvasElement, private readonly config: ViewConfig, private readonly model: LiveModel) {
    this.screen = new Layer(canvas);
    const world = config.world;
    for (const body of world?.objects ?? []) {
      if (body.category === "HUMAN" || body.category === "DYNAMIC") this.radii.set(body.name, (body.size[0] ?? 0.5) / 2);
    }
    this.robotSize = [world?.robot?.size[0] ?? 0.3, world?.robot?.size[1] ?? 0.3];
    this.robotOutline = robotOutline(world?.robot?.footprint);
    this.lidarMax = world?.robot?.lidar?.rangeMax ?? 3.5;
    const occupancy = config.occupancy;
    if (occupancy !== null && occupancy !== undefined) {
      const image = new Image();
      image.onload = () => {
        this.picture = { image, occupancy };
        this.drawRoomLayer();
      };
      image.src = occupancy.png;
    }
  }

  /** Fits the map to its box; redraws the static layers when the size changed. */
  resize(width: number, height: number, ratio: number): void {
    if (!this.screen.resize(width, height, ratio)) return;
    this.room.resize(width, height, ratio);
    this.marks.resize(width, height, ratio);
    this.transform = Transform.fit(worldBounds(this.config.world), width, height);
    this.drawRoomLayer();
    this.trailDrawn = 0;
    this.markersDrawn = 0;
  }

  /** The room, once per size, and again when the map's picture has loaded. */
  private drawRoomLayer(): void {
    const { width, height } = this.room;
    if (width === 0 || height === 0) return;
    this.room.reset();
    drawRoom(this.room.ctx, width, height, this.transform, this.config.world, this.config.paths, this.picture);
  }

  /** Takes the newest state into account (null: nothing new) and draws the frame. */
  draw(state: StateMessage | null): DrawnRobot | null {
    if (state !== null) this.applyMovers(state.objects);
    this.updateMarks();
    const ctx = this.screen.ctx;
    this.screen.paint(this.room);
    this.screen.paint(this.marks);
    this.drawGoals(ctx);
    this.drawMovers(ctx);
    const latest = this.model.latest;
    if (latest === null) return null;
    const zone = this.model.zone();
    const [x = 0, y = 0, , yaw = 0] = latest.robot.pose;
    this.drawLaser(ctx, latest, x, y, yaw);
    const odom = latest.robot.odom;
    const believed: [number, number, number] | null =
      odom !== undefined && odom.length >= 3 ? [odom[0] ?? 0, odom[1] ?? 0, odom[2] ?? 0] : null;
    if (believed !== null) this.drawRobot(ctx, believed, null);
    this.drawRobot(ctx, [x, y, yaw], zone);
    return { seq: latest.seq, t: latest.t, pose: [x, y, yaw], odom: believed,
      px: [this.transform.x(x), this.transform.y(y)], zone };
  }

  private applyMovers(objects: readonly MovingObject[]): void {
    for (const object of objects) {
      if (object.type !== "HUMAN" && object.type !== "DYNAMIC") continue;
      const mover = this.movers.get(object.name);
      const x = object.pose[0] ?? 0;
      const y = object.pose[1] ?? 0;
      if (mover !== undefined) {
        mover.x = x;
        mover.y = y;
      } else {
        this.movers.set(object.name, { x, y, radius: this.radii.get(object.name) ?? 0.25 });
      }
    }
  }

  get moverCount(): number {
    return this.movers.size;
  }

  /** Names of the moving objects at a world point (for the tooltip). */
  moverAt(x: number, y: number): string | null {
    for (const [name, mover] of this.movers) {
      if (Math.hypot(mover.x - x, mover.y - y) <= mover.radius) return name;
    }
    return null;
  }

  private updateMarks(): void {
    const ctx = this.marks.ctx;
    const tf = this.transform;
    const trail = this.model.trail;
    if (trail.length >= 4 && this.trailDrawn < trail.length - 2) {
      const from = Math.max(0, this.trailDrawn - 2);
      ctx.beginPath();
      ctx.moveTo(tf.x(trail[from] ?? 0), tf.y(trail[from + 1] ?? 0));
      for (let i = from + 2; i < trail.length; i += 2) ctx.lineTo(tf.x(trail[i] ?? 0), tf.y(trail[i + 1] ?? 0));
      ctx.strokeStyle = ROBOT_TRUE;
      ctx.globalAlpha = 0.45;
      ctx.lineWidth = 2;
      ctx.lineJoin = "round";
      ctx.stroke();
      ctx.globalAlpha = 1;
      this.trailDrawn = trail.length;
    }
    const signals = this.model.signals;
    const end = Math.min(signals.length, MAX_MARKERS);
    for (; this.markersDrawn < end; this.markersDrawn += 1) {
      const entry = signals[this.markersDrawn];
      if (entry === undefined || entry.x === null || entry.y === null) continue;
      ctx.beginPath();
      ctx.arc(tf.x(entry.x), tf.y(entry.y), 5, 0, 2 * Math.PI);
      ctx.fillStyle = signalColour(this.config.colours, entry.signal);
      ctx.fill();
      ctx.strokeStyle = "#fff";
      ctx.lineWidth = 1;
      ctx.stroke();
    }
  }

  private drawGoals(ctx: CanvasRenderingContext2D): void {
    const tf = this.transform;
    const tolerance = new Map((this.config.mission?.goals ?? []).map((g) => [g.index, g.tolerance]));
    ctx.font = "11px sans-serif";
    ctx.textAlign = "center";
    for (const task of this.model.tasks) {
      if (task.goal === null) continue;
      const [gx, gy] = task.goal;
      const colour = TASK[task.state];
      const r = Math.max(4, (tolerance.get(task.index) ?? 0.25) * tf.scale);
      ctx.beginPath();
      ctx.arc(tf.x(gx), tf.y(gy), r, 0, 2 * Math.PI);
      ctx.globalAlpha = 0.18;
      ctx.fillStyle = colour;
      ctx.fill();
      ctx.globalAlpha = 1;
      ctx.setLineDash([3, 2]);
      ctx.strokeStyle = colour;
      ctx.lineWidth = task.state === "ACTIVE" ? 2.5 : 1.5;
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = colour;
      ctx.fillText(`goal ${task.index}`, tf.x(gx), tf.y(gy) - r - 3);
    }
  }

  private drawMovers(ctx: CanvasRenderingContext2D): void {
    if (this.movers.size === 0) return;
    const tf = this.transform;
    ctx.beginPath();
    for (const mover of this.movers.values()) {
      const px = tf.x(mover.x);
      const py = tf.y(mover.y);
      ctx.moveTo(px + mover.radius * tf.scale, py);
      ctx.arc(px, py, mover.radius * tf.scale, 0, 2 * Math.PI);
    }
    ctx.globalAlpha = 0.8;
    ctx.fillStyle = HUMAN;
    ctx.fill();
    ctx.globalAlpha = 1;
    ctx.strokeStyle = "#5a2f08";
    ctx.lineWidth = 1;
    ctx.stroke();
  }

  private drawLaser(ctx: CanvasRenderingContext2D, state: StateMessage, x: number, y: number, yaw: number): void {
    const tf = this.transform;
    const ranges = state.robot.laser_ranges;
    if (ranges !== undefined && ranges.length > 0) {
      const step = (2 * Math.PI) / ranges.length;
      ctx.beginPath();
      for (let i = 0; i < ranges.length; i += 1) {
        const r = ranges[i] ?? Infinity;
        if (!Number.isFinite(r)) continue; // +inf: the beam hit nothing
        const a = yaw + i * step;
        const hx = tf.x(x + r * Math.cos(a));
        const hy = tf.y(y + r * Math.sin(a));
        ctx.moveTo(hx + 1.5, hy);
        ctx.arc(hx, hy, 1.5, 0, 2 * Math.PI);
      }
      ctx.fillStyle = LASER;
      ctx.fill();
      return;
    }
    const nearest = state.robot.laser_min;
    if (nearest !== undefined && Number.isFinite(nearest) && nearest <= this.lidarMax) {
      ctx.beginPath();
      ctx.arc(tf.x(x), tf.y(y), nearest * tf.scale, 0, 2 * Math.PI);
      ctx.strokeStyle = LASER;
      ctx.setLineDash([2, 3]);
      ctx.lineWidth = 1.5;
      ctx.stroke();
      ctx.setLineDash([]);
    }
  }

  /** The robot's footprint (its description's outline, else its box) with its heading; zone null draws the
   * odometry ghost (dashed, hollow). */
  private drawRobot(ctx: CanvasRenderingContext2D, pose: [number, number, number], zone: Zone | null): void {
    const tf = this.transform;
    const [x, y, yaw] = pose;
    const [sx, sy] = this.robotSize;
    const outline = this.robotOutline;
    ctx.beginPath();
    if (outline?.type === "circle") {
      // the circle's centre may lie off the robot's origin (a description's disc), so it turns with the pose
      const [[cx, cy]] = placed([[outline.x, outline.y]], x, y, yaw) as [[number, number]];
      ctx.arc(tf.x(cx), tf.y(cy), outline.radius * tf.scale, 0, 2 * Math.PI);
    } else {
      const corners = outline === null ? boxCorners(x, y, sx, sy, yaw) : placed(outline.points, x, y, yaw);
      for (const [cx, cy] of corners) ctx.lineTo(tf.x(cx), tf.y(cy));
      ctx.closePath();
    }
    if (zone !== null) {
      ctx.fillStyle = ZONE[zone];
      ctx.fill();
      ctx.strokeStyle = ROBOT_TRUE;
      ctx.lineWidth = 2;
    } else {
      ctx.setLineDash([4, 3]);
      ctx.strokeStyle = ROBOT_BELIEVED;
      ctx.lineWidth = 1.5;
    }
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.moveTo(tf.x(x), tf.y(y));
    ctx.lineTo(tf.x(x + Math.cos(yaw) * sx * 0.8), tf.y(y + Math.sin(yaw) * sx * 0.8));
    ctx.strokeStyle = zone !== null ? ROBOT_TRUE : ROBOT_BELIEVED;
    ctx.lineWidth = 2;
    ctx.stroke();
  }
}
