// SPDX-License-Identifier: EPL-2.0
// Frame-time statistics: how long each drawn frame took (script time in the requestAnimationFrame callback)
// and how far apart frames came, over a sliding window.

export interface FrameSummary {
  /** Frames measured in the window. */
  readonly frames: number;
  readonly meanMs: number;
  readonly p95Ms: number;
  readonly maxMs: number;
  /** Mean interval between animation frames (16.7 ms at 60 Hz). */
  readonly intervalMs: number;
}

const WINDOW = 600;

export class FrameStats {
  private readonly work = new Float64Array(WINDOW);
  private readonly gaps = new Float64Array(WINDOW);
  private count = 0;
  private previous: number | null = null;
  total = 0;

  record(workMs: number, frameStart: number): void {
    const slot = this.count % WINDOW;
    this.work[slot] = workMs;
    this.gaps[slot] = this.previous === null ? 0 : frameStart - this.previous;
    this.previous = frameStart;
    this.count += 1;
    this.total += 1;
  }

  /** Starts a new window (tests measure a phase of their own). */
  reset(): void {
    this.count = 0;
    this.previous = null;
  }

  summary(): FrameSummary {
    const n = Math.min(this.count, WINDOW);
    if (n === 0) return { frames: 0, meanMs: 0, p95Ms: 0, maxMs: 0, intervalMs: 0 };
    const work = Array.from(this.work.subarray(0, n)).sort((a, b) => a - b);
    const gaps = Array.from(this.gaps.subarray(0, n)).filter((g) => g > 0);
    const sum = work.reduce((a, b) => a + b, 0);
    return {
      frames: n,
      meanMs: sum / n,
      p95Ms: work[Math.min(n - 1, Math.floor(n * 0.95))] ?? 0,
      maxMs: work[n - 1] ?? 0,
      intervalMs: gaps.length > 0 ? gaps.reduce((a, b) => a + b, 0) / gaps.length : 0,
    };
  }
}
