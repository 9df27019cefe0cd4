// SPDX-License-Identifier: EPL-2.0
// Small helpers for building the diagram's SVG. World coordinates go in as metres with y up; `Y` negates y
// because SVG's y points down (the viewport's transform does the rest).

export const SVG_NS = "http://www.w3.org/2000/svg";

export type Attrs = Readonly<Record<string, string | number | null | undefined>>;

export function svg<K extends keyof SVGElementTagNameMap>(
  tag: K, attrs: Attrs = {}, parent?: Element | DocumentFragment): SVGElementTagNameMap[K] {
  const element = document.createElementNS(SVG_NS, tag);
  for (const [name, value] of Object.entries(attrs)) {
    if (value !== null && value !== undefined) element.setAttribute(name, String(value));
  }
  if (parent !== undefined) parent.appendChild(element);
  return element;
}

/** World y (up) to SVG y (down). */
export const Y = (y: number): number => -y;

/** Rounded for the DOM: millimetres are plenty, and short attributes keep a big room's page small. */
export const r = (value: number): number => Math.round(value * 1000) / 1000;

/** A polygon's `points` from world corners. */
export function points(corners: readonly (readonly [number, number])[]): string {
  return corners.map(([x, y]) => `${r(x)},${r(Y(y))}`).join(" ");
}

export function clear(element: Element): void {
  element.replaceChildren();
}
