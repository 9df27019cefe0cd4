// SPDX-License-Identifier: EPL-2.0
// The diagram as one SVG: layers in drawing order, the floors kept between renders (see floors.ts), the rest
// redrawn from each State. Marks (selection, issues, drop target) are classes on the elements, found through a
// registry by key (nameKey / goalKey), never by searching the DOM.
import type { CrowdDraft, PathDraft, RouteDraft, Selection } from "../model";
import { selectionKey } from "../model";
import type { RoomIndex } from "../room";
import { placed } from "../room";
import { clear, r, svg, Y } from "../svg";
import type { Footprint, Issue } from "../types";
import type { Bounds } from "../viewport";
import { Viewport } from "../viewport";
import { FloorLayer } from "./floors";
import type { Anchor } from "./issues";
import { IssueLabels, MAX_LABELS } from "./issues";
import type { Registry } from "./items";
import { drawGoals, drawMovers, drawObjects, drawRobot, drawWalls } from "./items";
import { drawDraft, drawDragPreview, drawFloorOutline, drawSideButtons } from "./overlay";
import { drawAreaRectangle, drawCrowd, drawCrowdDraft, drawGroup, drawRouteDraft, drawRoutedHuman } from "./people";

/** Label sizes in screen pixels, whatever the zoom. */
const LABEL_PX = 12;
const FLOOR_LABEL_PX = 9;

export interface RenderInput {
  index: RoomIndex;
  issues: ReadonlyMap<string, readonly Issue[]>;
  selection: Selection | null;
  draft: PathDraft | null;
  routeDraft?: RouteDraft | null;
  crowdDraft?: CrowdDraft | null;
}

export class DiagramView {
  readonly world: SVGGElement;
  readonly view: Viewport;
  private readonly floorLayer: FloorLayer;
  private readonly map: SVGGElement;
  private mapDrawn = "";
  private readonly walls: SVGGElement;
  private readonly route: SVGGElement;
  private readonly crowds: SVGGElement;
  private readonly objects: SVGGElement;
  private readonly movers: SVGGElement;
  private readonly robot: SVGGElement;
  private readonly goals: SVGGElement;
  private readonly floorLabels: SVGGElement;
  private readonly labels: SVGGElement;
  private readonly overlay: SVGGElement;
  private readonly overlayLabels: SVGGElement;
  private readonly preview: SVGGElement;
  private readonly issueLabels: IssueLabels;
  private registry: Registry = new Map();
  private marked: Element[] = [];
  private index: RoomIndex | null = null;
  private labelledFloors = 0;

  constructor(readonly root: SVGSVGElement, labelBox: HTMLElement) {
    this.world = svg("g", { class: "world" }, root);
    const layer = (name: string): SVGGElement => svg("g", { class: `layer ${name}` }, this.world);
    this.map = layer("map");
    const floors = layer("floors");
    const ghosts = layer("ghosts");
    this.walls = layer("walls");
    // crowds' areas lie on the floors, under everything that stands or walks on them
    this.crowds = layer("crowds");
    this.route = layer("route");
    // paths under furniture: a path's wide hit stroke would otherwise cover the furniture it passes
    this.movers = layer("movers");
    this.objects = layer("objects");
    this.robot = layer("robot");
    this.floorLabels = layer("floor-labels");
    this.labels = layer("labels");
    // goal markers over the names: a marker is small and its number is what the user looks for
    this.goals = layer("goals");
    this.overlay = layer("overlay");
    this.preview = layer("preview");
    this.overlayLabels = layer("labels overlay-labels");
    this.floorLayer = new FloorLayer(floors, ghosts, this.floorLabels);
    this.view = new Viewport(root, this.world);
    this.issueLabels = new IssueLabels(labelBox, this.view);
    this.view.onChange(() => this.zoomed());
  }

  get ghostCount(): number {
    return this.floorLayer.ghostsShown;
  }

  render(input: RenderInput): void {
    const { index } = input;
    this.index = index;
    this.drawMap(index);
    if (this.floorLayer.update(index)) this.labelledFloors = index.placed.length;
    const registry: Registry = new Map();
    for (const group of [this.walls, this.crowds, this.route, this.objects, this.movers, this.robot, this.goals,
      this.labels, this.overlay, this.overlayLabels, this.preview]) clear(group);
    drawWalls(this.walls, index, registry);
    drawObjects(this.objects, this.labels, index.diagram.objects, registry);
    const d = index.diagram;
    drawMovers(this.movers, this.labels, d.movers.filter((m) => m.route == null), registry);
    for (const mover of d.movers) {
      if (mover.route != null) drawRoutedHuman(this.movers, this.labels, index, mover, registry);
    }
    for (const group of d.groups ?? []) drawGroup(this.movers, this.labels, index, group, registry);
    for (const crowd of d.crowds ?? []) drawCrowd(this.crowds, this.labels, index, crowd, registry);
    drawRobot(this.robot, this.labels, index.diagram.robot, registry);
    drawGoals(this.goals, this.route, index, registry);
    this.registry = registry;
    this.mark(input);
    if (input.draft !== null) drawDraft(this.overlay, this.overlayLabels, index, input.draft);
    if (input.routeDraft != null) drawRouteDraft(this.overlay, this.overlayLabels, index, input.routeDraft);
    if (input.crowdDraft != null) drawCrowdDraft(this.overlay, index, input.crowdDraft);
    const drafting = input.draft !== null || input.routeDraft != null || input.crowdDraft != null;
    const selected = input.selection;
    if (selected !== null && selected.kind === "floor" && index.editableLayout && !drafting) {
      const floor = index.floors.get(selected.name);
      if (floor !== undefined && placed(floor)) drawSideButtons(this.overlay, index, floor);
    }
    if (selected !== null && selected.kind === "floor") {
      // the floor's own outline is partly painted over by its neighbours (drawn later): outline it on top
      const floor = index.floors.get(selected.name);
      if (floor !== undefined && placed(floor)) drawFloorOutline(this.overlay, index, floor);
    }
    this.showIssueLabels(input);
    this.zoomed();
  }

  /** A room from an occupancy map: the map's picture under the floors (which the page's style makes translucent
   * over it), its first row at the top, cells kept sharp; replaced only when the picture or its place changed. */
  private drawMap(index: RoomIndex): void {
    const box = index.pictureBox();
    const png = index.occupancy?.png ?? "";
    const drawn = box === null ? "" : `${png.length}:${png.slice(-64)}:${box.join(",")}`;
    this.root.classList.toggle("over-map", box !== null);
    if (drawn === this.mapDrawn) return;
    this.mapDrawn = drawn;
    clear(this.map);
    if (box === null) return;
    const [x0, y0, x1, y1] = box;
    svg("image", { href: png, x: r(x0), y: r(Y(y1)), width: r(x1 - x0), height: r(y1 - y0),
      preserveAspectRatio: "none", "image-rendering": "pixelated", "data-kind": "map" }, this.map);
  }

  /** The classes `selected` and `has-issue`: on floors through the floor layer, on the rest through the registry. */
  private mark(input: RenderInput): void {
    for (const element of this.marked) element.classList.remove("selected", "has-issue");
    this.marked = [];
    const issueFloors: string[] = [];
    for (const key of input.issues.keys()) {
      const element = this.registry.get(key);
      if (element !== undefined) {
        element.classList.add("has-issue");
        this.marked.push(element);
      } else if (key.startsWith("n:")) {
        issueFloors.push(key.slice(2));
      }
    }
    this.floorLayer.mark("has-issue", issueFloors);
    const selection = input.selection;
    const selectedFloors: string[] = [];
    if (selection !== null) {
      const element = this.registry.get(selectionKey(selection));
      if (element !== undefined) {
        element.classList.add("selected");
        this.marked.push(element);
      } else if (selection.kind === "floor") {
        selectedFloors.push(selection.name);
      }
    }
    this.floorLayer.mark("selected", selectedFloors);
  }

  private showIssueLabels(input: RenderInput): void {
    const entries: [Anchor, readonly Issue[]][] = [];
    for (const [key, issues] of input.issues) {
      if (entries.length >= MAX_LABELS) break;
      const anchor = this.anchor(key, input.index);
      if (anchor !== null) entries.push([anchor, issues]);
    }
    this.issueLabels.show(entries);
  }

  /** Where an element's issue label goes. */
  anchor(key: string, index: RoomIndex): Anchor | null {
    const diagram = index.diagram;
    if (key.startsWith("g:")) {
      const at = Number(key.slice(2));
      const goal = diagram.mission?.goals.find((g) => g.index === at);
      if (goal === undefined || goal.x === null || goal.y === null) return null;
      return { x: goal.x, y: goal.y, reach: index.size * 0.3, name: goal.floor ?? "", kind: "goal", index: at };
    }
    const name = key.slice(2);
    const item = diagram.robot?.name === name ? diagram.robot : diagram.objects.find((o) => o.name === name);
    if (item !== undefined && item !== null) {
      if (item.x === null || item.y === null) return null;
      const reach = Math.max(item.footprint?.sizeX ?? 0.3, item.footprint?.sizeY ?? 0.3) / 2;
      return { x: item.x, y: item.y, reach, name, kind: item.kind, index: null };
    }
    // people who see the robot: a routed person's or a group's first stop, a crowd's first from floor
    const routed = diagram.movers.find((m) => m.name === name && m.route != null);
    const group = diagram.groups?.find((g) => g.name === name);
    const crowd = diagram.crowds?.find((c) => c.name === name);
    const places = routed?.route?.stops ?? group?.route?.stops ?? crowd?.from;
    if (places !== undefined) {
      const first = places.find((p) => p.x !== null && p.y !== null);
      if (first === undefined || first.x === null || first.y === null) return null;
      const kind = routed !== undefined ? "human" : group !== undefined ? "group" : "crowd";
      return { x: first.x, y: first.y, reach: 0.3, name, kind, index: null };
    }
    const mover = diagram.movers.find((m) => m.name === name);
    if (mover !== undefined) {
      const first = mover.points.find((p) => p.x !== null && p.y !== null);
      if (first === undefined || first.x === null || first.y === null) return null;
      return { x: first.x, y: first.y, reach: 0.3, name, kind: mover.kind, index: null };
    }
    const wall = diagram.room?.walls.find((w) => w.name === name);
    if (wall !== undefined) {
      return { x: wall.x, y: wall.y, reach: Math.max(wall.sizeX, wall.sizeY) / 2, name, kind: "wall", index: null };
    }
    const floor = index.floors.get(name);
    if (floor !== undefined && placed(floor)) {
      return { x: floor.centreX, y: floor.centreY, reach: index.size / 2, name, kind: "floor", index: null };
    }
    return null;
  }

  /** The element a key names, if drawn (tests and the issues panel). */
  element(key: string): Element | undefined {
    return this.registry.get(key) ?? (key.startsWith("n:") ? this.floorLayer.rect(key.slice(2)) : undefined);
  }

  /** Shows what a drag would do: the footprint on the floor under the pointer, that floor outlined. */
  dragPreview(at: [number, number], footprint: Footprint, yaw: number, floor: string | null): void {
    clear(this.preview);
    drawDragPreview(this.preview, at, footprint, yaw, floor !== null);
    this.floorLayer.mark("drop-target", floor === null ? [] : [floor]);
  }

  /** The rectangle of floors being dragged for a crowd's area. */
  areaPreview(a: [number, number], b: [number, number], which: "from" | "to"): void {
    clear(this.preview);
    drawAreaRectangle(this.preview, a, b, which);
  }

  clearPreview(): void {
    clear(this.preview);
    this.floorLayer.mark("drop-target", []);
  }

  /** The room and everything on it, for fit-to-room. */
  bounds(): Bounds {
    const index = this.index;
    const box = [Infinity, Infinity, -Infinity, -Infinity];
    const grow = (x: number, y: number, reach = 0): void => {
      box[0] = Math.min(box[0] ?? 0, x - reach);
      box[1] = Math.min(box[1] ?? 0, y - reach);
      box[2] = Math.max(box[2] ?? 0, x + reach);
      box[3] = Math.max(box[3] ?? 0, y + reach);
    };
    if (index !== null) {
      const half = index.size / 2;
      // a graph room's ghosts lie one cell outside: keep them on screen, they are what the user adds
      const around = index.editableLayout ? index.size : 0;
      for (const floor of index.placed) grow(floor.centreX, floor.centreY, half + around);
      for (const wall of index.diagram.room?.walls ?? []) grow(wall.x, wall.y, Math.max(wall.sizeX, wall.sizeY) / 2);
      const picture = index.pictureBox();  // a map room: its whole map, not only the free floors
      if (picture !== null) {
        grow(picture[0], picture[1]);
        grow(picture[2], picture[3]);
      }
    }
    const [x0 = 0, y0 = 0, x1 = 1, y1 = 1] = box;
    return Number.isFinite(x0) ? [x0, y0, x1, y1] : [0, 0, 1, 1];
  }

  fit(): void {
    this.view.fit(this.bounds());
  }

  /** Labels keep their screen size; floor names go when the floors get too small to carry them. */
  private zoomed(): void {
    const k = this.view.k;
    for (const group of [this.labels, this.overlayLabels]) group.setAttribute("font-size", String(LABEL_PX / k));
    this.floorLabels.setAttribute("font-size", String(FLOOR_LABEL_PX / k));
    const size = this.index?.size ?? 1;
    this.floorLabels.style.display = this.labelledFloors > 0 && k * size >= 42 ? "" : "none";
    // names of things smaller than a few pixels would be a cloud of text over nothing
    this.labels.style.display = k * size >= 22 ? "" : "none";
    this.issueLabels.position();
  }
}
