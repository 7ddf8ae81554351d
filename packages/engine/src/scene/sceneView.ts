/**
 * SceneView: the scene as the scene rules (sceneRules.ts) check an action against it, at the
 * action's time: bodies (positions may be unknown when a caller cannot simulate), lines and points,
 * the globals, and the indexes the checks look near an action in: a DiscGrid of the bodies of known
 * position, and the lines and points by place (sim/obstacleCells.ts, built once a few discs have
 * checked). A lazy view reads its bodies only when an action needs them all: it asks its source (a
 * Timeline's World) for one body, or for the bodies near a disc or a segment, and tests those with
 * the scene's own rules (overlap.ts), so that its answers are the ones reading every body gives.
 */
import { ObstacleCells } from "../sim/obstacleCells.js";
import { DiscGrid } from "./discGrid.js";
import { discsOverlap } from "./overlap.js";
import type { LineKind, Vec2 } from "./types.js";

/**
 * Discs a view checks by a scan of its lines and points before it indexes them: a Timeline makes a
 * view per instant with actions, and indexing every line for the one disc an instant adds cost more
 * than the scan (1,000 instants of 10 discs among 5,000 segments: 1 s more).
 */
const SCAN_CHECKS = 8;

export interface ViewBody {
  x: number;
  y: number;
  r: number;
  mu: number;
  /** false when the position at the view's time is unknown (validation without a simulation) */
  known: boolean;
}
export interface ViewLine {
  p1: Vec2;
  p2: Vec2;
  kind: LineKind;
}

export interface ViewSource {
  time: number;
  g: number;
  gravity: Vec2;
  bodies: readonly { id: string; x: number; y: number; r: number; mu: number }[];
  lines: readonly { id: string; p1: Vec2; p2: Vec2; kind: LineKind }[];
  points: readonly { id: string; p: Vec2 }[];
}

/** A body's disc at the view's time: visited by a lazy view's source (see forEachBodyNear). */
export type DiscVisitor = (id: string, x: number, y: number, r: number) => void;

/** A state whose bodies are read only when an action needs them all (SceneView.lazy). */
export interface LazyViewSource extends Omit<ViewSource, "bodies"> {
  bodies(): ViewSource["bodies"];
  hasBody(id: string): boolean;
  /** Body `id` as `bodies()` gives it (it exists: hasBody). */
  body(id: string): { x: number; y: number; r: number; mu: number };
  /** Visits every body that could overlap the disc (x, y, r), and perhaps others, each as
   *  `bodies()` gives it (a World's placement candidates: sim/placement.ts). */
  forEachBodyNear(x: number, y: number, r: number, visit: DiscVisitor): void;
  /** The same for the segment (x1, y1)-(x2, y2), a point when both ends are equal. */
  forEachBodyNearSegment(x1: number, y1: number, x2: number, y2: number, visit: DiscVisitor): void;
}

export class SceneView {
  time: number;
  g: number;
  gravity: Vec2;
  readonly lines = new Map<string, ViewLine>();
  readonly points = new Map<string, Vec2>();
  private readonly bodyMap = new Map<string, ViewBody>();
  private readonly discs = new DiscGrid();
  /** `lines` and `points` by place, built when a disc is first checked against them. */
  private lineCells: ObstacleCells<ViewLine> | null = null;
  private pointCells: ObstacleCells<Vec2> | null = null;
  private discChecks = 0;
  /** Of a lazy view, the source its bodies are read from (null once they are). */
  private source: LazyViewSource | null = null;

  constructor(time: number, g: number, gravity: Vec2) {
    this.time = time;
    this.g = g;
    this.gravity = gravity;
  }

  /** A view of a known state (all positions known). */
  static of(s: ViewSource): SceneView {
    const v = new SceneView(s.time, s.g, s.gravity);
    v.addBodies(s.bodies);
    for (const l of s.lines) v.lines.set(l.id, { p1: l.p1, p2: l.p2, kind: l.kind });
    for (const p of s.points) v.points.set(p.id, p.p);
    return v;
  }

  /**
   * A view of a known state whose bodies are read from `s` only when an action needs them all (a
   * body added, moved or checked against a line or point, a change of gravity): a group of actions
   * that only give velocities to bodies or remove them asks `s.hasBody` alone (reading a million
   * bodies for each such group made a scene's later actions cost seconds each), and a body added
   * or moved asks `s` for the bodies near it (reading every body for each instant that added one
   * made a scene built one body per instant quadratic). Until then `s` must give the state at the
   * view's time with every action this view checked applied (a World the group's actions are
   * applied to as they are checked does).
   */
  static lazy(s: LazyViewSource): SceneView {
    const v = SceneView.of({ ...s, bodies: [] });
    v.source = s;
    return v;
  }

  private addBodies(bodies: ViewSource["bodies"]): void {
    for (const b of bodies) {
      this.bodyMap.set(b.id, { x: b.x, y: b.y, r: b.r, mu: b.mu, known: true });
      this.discs.add(b.id, b.x, b.y, b.r); // ids are unique in a state
    }
  }

  /** The bodies, read from a lazy view's source first. */
  get bodies(): Map<string, ViewBody> {
    if (this.source !== null) {
      const s = this.source;
      this.source = null;
      this.addBodies(s.bodies());
    }
    return this.bodyMap;
  }

  /** Whether body `id` is in the view (without reading a lazy view's bodies). */
  hasBody(id: string): boolean {
    return this.source === null ? this.bodyMap.has(id) : this.source.hasBody(id);
  }

  /** Body `id`, or undefined (without reading a lazy view's bodies). */
  body(id: string): ViewBody | undefined {
    if (this.source === null) return this.bodyMap.get(id);
    if (!this.source.hasBody(id)) return undefined;
    const b = this.source.body(id);
    return { x: b.x, y: b.y, r: b.r, mu: b.mu, known: true };
  }

  /** Sets body `id` (new, or in place of the one of that id); a lazy view's source gets it when the
   *  action is applied to it. */
  setBody(id: string, b: ViewBody): void {
    if (this.source !== null) return;
    this.bodyMap.set(id, b);
    if (b.known) this.discs.insert(id, b.x, b.y, b.r);
  }

  /** Removes body `id` (in the view: `hasBody(id)`); a lazy view's source, when the action is applied. */
  removeBody(id: string): void {
    if (this.source !== null) return;
    this.bodyMap.delete(id);
    this.discs.remove(id);
  }

  /** The smallest id of a body of known position other than `except` that the disc (x, y, r)
   *  overlaps (discsOverlap), or null; a lazy view tests its source's bodies near the disc. */
  overlapOf(x: number, y: number, r: number, except: string): string | null {
    if (this.source === null) return this.discs.findOverlap(x, y, r, except);
    let best: string | null = null;
    this.source.forEachBodyNear(x, y, r, (id, bx, by, br) => {
      if (id !== except && (best === null || id < best) && discsOverlap(x, y, r, bx, by, br)) best = id;
    });
    return best;
  }

  /** The smallest id of a body of known position near the segment (x1, y1)-(x2, y2) (a point: both
   *  ends equal) for which `hits(x, y, r)` holds, or null (DiscGrid.smallestNearSegment; a lazy view
   *  tests its source's bodies near the segment). */
  smallestNearSegment(
    x1: number,
    y1: number,
    x2: number,
    y2: number,
    hits: (x: number, y: number, r: number) => boolean,
  ): string | null {
    if (this.source === null) return this.discs.smallestNearSegment(x1, y1, x2, y2, hits);
    let best: string | null = null;
    this.source.forEachBodyNearSegment(x1, y1, x2, y2, (id, bx, by, br) => {
      if ((best === null || id < best) && hits(bx, by, br)) best = id;
    });
    return best;
  }

  /** Sets line `id` (new or moved). */
  setLine(id: string, line: ViewLine): void {
    this.lines.set(id, line);
    if (this.lineCells !== null) indexLine(this.lineCells, id, line);
  }

  deleteLine(id: string): void {
    this.lines.delete(id);
    this.lineCells?.delete(id);
  }

  /** Sets point `id` (new or moved). */
  setPoint(id: string, p: Vec2): void {
    this.points.set(id, p);
    this.pointCells?.set(id, p, p[0], p[1], p[0], p[1], true);
  }

  deletePoint(id: string): void {
    this.points.delete(id);
    this.pointCells?.delete(id);
  }

  /**
   * The lines and the points indexed by place, for a disc about to be checked; null for the first
   * SCAN_CHECKS discs of the view (scan `lines` and `points` then), built from them after.
   */
  obstacleCells(): [ObstacleCells<ViewLine>, ObstacleCells<Vec2>] | null {
    if (this.lineCells === null || this.pointCells === null) {
      if (++this.discChecks <= SCAN_CHECKS) return null;
      // the view has scanned already: the index answers from its first query
      this.lineCells = new ObstacleCells<ViewLine>({ scanQueries: 0 });
      this.pointCells = new ObstacleCells<Vec2>({ scanQueries: 0 });
      for (const [id, l] of this.lines) indexLine(this.lineCells, id, l);
      for (const [id, p] of this.points) this.pointCells.set(id, p, p[0], p[1], p[0], p[1], true);
    }
    return [this.lineCells, this.pointCells];
  }

  /** Time moves on without a simulation: every body's position becomes unknown. */
  forgetPositions(time: number): void {
    this.time = time;
    for (const b of this.bodies.values()) b.known = false;
    this.discs.clear();
  }
}

/** Put `line` in `cells` (a segment by place; a line or ray is tested by every query). */
function indexLine(cells: ObstacleCells<ViewLine>, id: string, l: ViewLine): void {
  cells.set(id, l, l.p1[0], l.p1[1], l.p2[0], l.p2[1], l.kind === "segment");
}
