// SPDX-License-Identifier: EPL-2.0
// Zoom and pan of the diagram. The drawing is in metres with y negated (SVG's y points down, the room's up), in
// one <g> whose transform this sets: zooming or panning changes one attribute, never the 10,000 floors below it.
// Strokes use `vector-effect: non-scaling-stroke` (edit.css), and labels take their font size from the scale
// (`labelPx / k` on their group), so lines and text keep their screen size at any zoom.

export type Bounds = readonly [number, number, number, number];

export class Viewport {
  /** Screen pixels per metre, and the screen position of world (0, 0). */
  k = 50;
  tx = 0;
  ty = 0;
  private listeners: (() => void)[] = [];

  constructor(private readonly svg: SVGSVGElement, private readonly world: SVGGElement) {}

  onChange(listener: () => void): void {
    this.listeners.push(listener);
  }

  get width(): number {
    return this.svg.clientWidth || 800;
  }

  get height(): number {
    return this.svg.clientHeight || 600;
  }

  /** Screen pixel (relative to the SVG) to world metres. */
  toWorld(px: number, py: number): [number, number] {
    return [(px - this.tx) / this.k, (this.ty - py) / this.k];
  }

  toScreen(wx: number, wy: number): [number, number] {
    return [this.tx + wx * this.k, this.ty - wy * this.k];
  }

  /** The pointer's position relative to the SVG. */
  local(event: { clientX: number; clientY: number }): [number, number] {
    const box = this.svg.getBoundingClientRect();
    return [event.clientX - box.left, event.clientY - box.top];
  }

  /** Shows the whole of [xmin, ymin, xmax, ymax] (world metres), centred. */
  fit(bounds: Bounds, pad = 32): void {
    const [xmin, ymin, xmax, ymax] = bounds;
    const w = Math.max(xmax - xmin, 1e-3);
    const h = Math.max(ymax - ymin, 1e-3);
    this.k = Math.max(1e-3, Math.min((this.width - 2 * pad) / w, (this.height - 2 * pad) / h));
    this.tx = (this.width - w * this.k) / 2 - xmin * this.k;
    this.ty = (this.height + h * this.k) / 2 + ymin * this.k;
    this.changed();
  }

  /** Zooms by `factor` keeping the world point under screen pixel (px, py) where it is. */
  zoomAt(px: number, py: number, factor: number): void {
    const k = Math.min(4000, Math.max(0.5, this.k * factor));
    const [wx, wy] = this.toWorld(px, py);
    this.k = k;
    this.tx = px - wx * k;
    this.ty = py + wy * k;
    this.changed();
  }

  pan(dx: number, dy: number): void {
    this.tx += dx;
    this.ty += dy;
    this.changed();
  }

  private changed(): void {
    this.world.setAttribute("transform", `translate(${this.tx} ${this.ty}) scale(${this.k})`);
    for (const listener of this.listeners) listener();
  }
}
