// SPDX-License-Identifier: EPL-2.0
// Every pointer gesture on the diagram goes through one set of listeners on the <svg> (event delegation): the
// element under the pointer is found with closest("[data-kind]"), so 10,000 floors need no listener each.
// A press that moves less than DRAG_PX is a click; more is a drag of the pressed element when the tools allow
// it (furniture, the robot) and otherwise pans the view. Pointer capture keeps a drag going outside the SVG.
// Plain pointerdown/move/up, so Playwright's page.mouse drives it like a user.
import type { Viewport } from "../viewport";

const DRAG_PX = 4;

export interface DragSession {
  move(world: [number, number]): void;
  drop(world: [number, number]): void;
  cancel(): void;
}

export interface PointerHandlers {
  click(target: Element | null, world: [number, number], event: PointerEvent): void;
  /** A session when the pressed element can be dragged now, else null (the gesture pans). */
  drag(target: Element | null, world: [number, number]): DragSession | null;
  hover(world: [number, number] | null): void;
}

/** The diagram element (or add-wall button) an event is on. */
export function hit(target: EventTarget | null): Element | null {
  return target instanceof Element ? target.closest("[data-kind], [data-add-wall]") : null;
}

export function installPointer(svg: SVGSVGElement, view: Viewport, handlers: PointerHandlers): void {
  let press: {
    id: number; x: number; y: number; lastX: number; lastY: number; target: Element | null; moved: boolean;
    session: DragSession | null;
  } | null = null;

  svg.addEventListener("pointerdown", (event) => {
    if (event.button !== 0 && event.button !== 1) return;
    if (press !== null) return;
    event.preventDefault();
    const [x, y] = view.local(event);
    press = { id: event.pointerId, x, y, lastX: x, lastY: y, target: hit(event.target), moved: false, session: null };
    try {
      svg.setPointerCapture(event.pointerId);
    } catch {
      // synthetic events (tests) have no active pointer to capture; the listeners still get them
    }
  });

  svg.addEventListener("pointermove", (event) => {
    const [x, y] = view.local(event);
    if (press === null || press.id !== event.pointerId) {
      handlers.hover(view.toWorld(x, y));
      return;
    }
    if (!press.moved) {
      if (Math.hypot(x - press.x, y - press.y) < DRAG_PX) return;
      press.moved = true;
      press.session = event.buttons === 4 ? null : handlers.drag(press.target, view.toWorld(press.x, press.y));
      svg.classList.toggle("panning", press.session === null);
      svg.classList.toggle("dragging", press.session !== null);
    }
    if (press.session !== null) press.session.move(view.toWorld(x, y));
    else view.pan(x - press.lastX, y - press.lastY);
    press.lastX = x;
    press.lastY = y;
  });

  const end = (event: PointerEvent, cancelled: boolean): void => {
    if (press === null || press.id !== event.pointerId) return;
    const done = press;
    press = null;
    svg.classList.remove("panning", "dragging");
    if (svg.hasPointerCapture(event.pointerId)) svg.releasePointerCapture(event.pointerId);
    const [x, y] = view.local(event);
    if (cancelled) done.session?.cancel();
    else if (done.session !== null) done.session.drop(view.toWorld(x, y));
    else if (!done.moved) handlers.click(done.target, view.toWorld(x, y), event);
  };
  svg.addEventListener("pointerup", (event) => end(event, false));
  svg.addEventListener("pointercancel", (event) => end(event, true));
  svg.addEventListener("pointerleave", () => handlers.hover(null));

  svg.addEventListener("wheel", (event) => {
    event.preventDefault();
    const [x, y] = view.local(event);
    // pixels, lines or pages: a line is about 16 px, a page about 400
    const scale = event.deltaMode === 1 ? 16 : event.deltaMode === 2 ? 400 : 1;
    view.zoomAt(x, y, Math.exp(-event.deltaY * scale * 0.0015));
  }, { passive: false });
}
