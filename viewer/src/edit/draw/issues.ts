// SPDX-License-Identifier: EPL-2.0
// Validation issues on the diagram: the elements get the class `has-issue` (a red outline, edit.css) and each
// gets a label with the messages next to it, as HTML over the SVG so that it keeps its size and wraps like text
// at any zoom. Labels ignore the pointer (the element under one stays clickable); the issues panel is where
// an issue is clicked. Only the first MAX_LABELS elements get a label, so a room full of errors stays usable.
import type { Issue } from "../types";
import type { Viewport } from "../viewport";

export const MAX_LABELS = 60;

export interface Anchor {
  /** World point of the element and how far its outline reaches from it (metres). */
  x: number;
  y: number;
  reach: number;
  /** data-for: the element's name (a goal: its floor), with the kind and goal index for the test hooks. */
  name: string;
  kind: string;
  index: number | null;
}

interface Placed {
  element: HTMLElement;
  anchor: Anchor;
  width: number;
  height: number;
}

export class IssueLabels {
  private placed: Placed[] = [];

  constructor(private readonly box: HTMLElement, private readonly view: Viewport) {}

  show(entries: readonly (readonly [Anchor, readonly Issue[]])[]): void {
    this.box.replaceChildren();
    this.placed = [];
    for (const [anchor, issues] of entries.slice(0, MAX_LABELS)) {
      const element = document.createElement("div");
      const worst = issues.some((i) => i.severity === "error") ? "error"
        : issues.some((i) => i.severity === "warning") ? "warning" : "info";
      element.className = `issue-label ${worst}`;
      element.dataset.for = anchor.name;
      element.dataset.kind = anchor.kind;
      if (anchor.index !== null) element.dataset.index = String(anchor.index);
      // the name says which element a label is for where several stand close (a floor taken twice)
      const name = document.createElement("b");
      name.textContent = anchor.kind === "goal" && anchor.index !== null ? `goal ${anchor.index + 1} (${anchor.name})`
        : anchor.name;
      element.appendChild(name);
      for (const issue of issues) {
        const line = document.createElement("div");
        line.textContent = issue.message;
        element.appendChild(line);
      }
      this.box.appendChild(element);
      this.placed.push({ element, anchor, width: 0, height: 0 });
    }
    // measured once here, not on every zoom step
    for (const label of this.placed) {
      label.width = label.element.offsetWidth;
      label.height = label.element.offsetHeight;
    }
    this.position();
  }

  /** Next to each element, above-right; a label that would cover an earlier one moves down below it. */
  position(): void {
    const taken: { x0: number; x1: number; y0: number; y1: number }[] = [];
    const order = [...this.placed].sort((a, b) => b.anchor.y - a.anchor.y);
    for (const label of order) {
      const [sx, sy] = this.view.toScreen(label.anchor.x, label.anchor.y);
      const reach = label.anchor.reach * this.view.k;
      const x0 = sx + Math.min(reach, 40) * 0.7 + 4;
      let y0 = sy - Math.min(reach, 40) * 0.7 - label.height;
      const width = label.width;
      for (const other of taken) {
        if (x0 < other.x1 && x0 + width > other.x0 && y0 < other.y1 && y0 + label.height > other.y0) y0 = other.y1 + 2;
      }
      taken.push({ x0, x1: x0 + width, y0, y1: y0 + label.height });
      label.element.style.transform = `translate(${Math.round(x0)}px, ${Math.round(y0)}px)`;
    }
  }
}
