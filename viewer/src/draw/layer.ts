// SPDX-License-Identifier: EPL-2.0
// A canvas sized in device pixels whose context draws in CSS pixels.

export class Layer {
  readonly ctx: CanvasRenderingContext2D;
  width = 0;
  height = 0;
  ratio = 1;

  constructor(readonly canvas: HTMLCanvasElement = document.createElement("canvas")) {
    const ctx = canvas.getContext("2d");
    if (ctx === null) throw new Error("no 2D canvas context");
    this.ctx = ctx;
  }

  /** Resizes (clearing) to width x height CSS pixels; false when the size did not change. */
  resize(width: number, height: number, ratio: number): boolean {
    if (width === this.width && height === this.height && ratio === this.ratio) return false;
    this.width = width;
    this.height = height;
    this.ratio = ratio;
    this.canvas.width = Math.max(1, Math.round(width * ratio));
    this.canvas.height = Math.max(1, Math.round(height * ratio));
    this.canvas.style.width = `${width}px`;
    this.canvas.style.height = `${height}px`;
    this.reset();
    return true;
  }

  /** Back to CSS-pixel drawing, everything cleared. */
  reset(): void {
    this.ctx.setTransform(1, 0, 0, 1, 0, 0);
    this.ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    this.ctx.setTransform(this.ratio, 0, 0, this.ratio, 0, 0);
  }

  /** Copies another layer of the same size over this one, pixel for pixel. */
  paint(other: Layer): void {
    this.ctx.setTransform(1, 0, 0, 1, 0, 0);
    this.ctx.drawImage(other.canvas, 0, 0);
    this.ctx.setTransform(this.ratio, 0, 0, this.ratio, 0, 0);
  }
}
