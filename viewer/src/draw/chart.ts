// SPDX-License-Identifier: EPL-2.0
// The running total of the signals' utilities as a step line over simulation time (thesis Fig. 33), with
// stream gaps as red ticks and the faults' windows shaded behind it (as the report shades them). Redrawn only when
// something changed.
import type { FaultWindow, Gap } from "../model";
import { Layer } from "./layer";

const PAD = { left: 38, right: 8, top: 8, bottom: 18 };
/** The report's fault window colour (rei.report.charts). */
export const FAULT_FILL = "rgba(245, 166, 35, 0.18)";

export class UtilityChart {
  private readonly layer: Layer;

  constructor(canvas: HTMLCanvasElement) {
    this.layer = new Layer(canvas);
  }

  resize(width: number, height: number, ratio: number): boolean {
    return this.layer.resize(width, height, ratio);
  }

  draw(series: readonly (readonly [number, number])[], now: number, gaps: readonly Gap[],
       faults: readonly FaultWindow[] = []): void {
    const { ctx, width, height } = this.layer;
    this.layer.reset();
    const tmax = Math.max(1, now, series.at(-1)?.[0] ?? 0);
    let lo = 0;
    let hi = 0;
    for (const [, total] of series) {
      lo = Math.min(lo, total);
      hi = Math.max(hi, total);
    }
    if (hi - lo < 10) hi = lo + 10;
    const w = width - PAD.left - PAD.right;
    const h = height - PAD.top - PAD.bottom;
    const px = (t: number): number => PAD.left + (t / tmax) * w;
    const py = (v: number): number => PAD.top + (1 - (v - lo) / (hi - lo)) * h;
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, width, height);
    ctx.fillStyle = FAULT_FILL;
    for (const span of faults) {
      const end = Math.min(span.end ?? tmax, tmax); // an open window reaches the latest time
      ctx.fillRect(px(span.begin), PAD.top, Math.max(px(end) - px(span.begin), 1), h);
    }
    ctx.strokeStyle = "#ccc";
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(PAD.left, py(0));
    ctx.lineTo(PAD.left + w, py(0));
    ctx.stroke();
    ctx.fillStyle = "#666";
    ctx.font = "10px sans-serif";
    ctx.textAlign = "right";
    ctx.fillText(`${Math.round(hi)}`, PAD.left - 4, PAD.top + 8);
    ctx.fillText(`${Math.round(lo)}`, PAD.left - 4, PAD.top + h);
    ctx.textAlign = "center";
    ctx.fillText(`${tmax.toFixed(0)} s`, PAD.left + w - 12, height - 4);
    ctx.fillText("0", PAD.left, height - 4);
    ctx.strokeStyle = "#d62728";
    for (const gap of gaps) {
      ctx.beginPath();
      ctx.moveTo(px(gap.t), PAD.top);
      ctx.lineTo(px(gap.t), PAD.top + h);
      ctx.stroke();
    }
    ctx.beginPath();
    let previous = 0;
    ctx.moveTo(px(0), py(0));
    for (const [t, total] of series) {
      ctx.lineTo(px(t), py(previous));
      ctx.lineTo(px(t), py(total));
      previous = total;
    }
    ctx.lineTo(px(Math.max(now, series.at(-1)?.[0] ?? 0)), py(previous));
    ctx.strokeStyle = "#1f3a93";
    ctx.lineWidth = 2;
    ctx.stroke();
  }
}
