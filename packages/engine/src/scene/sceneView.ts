/**
 * SceneView: the scene as the scene rules (sceneRules.ts) check an action against it, at the
 * action's time: bodies (positions may be unknown when a caller cannot simulate), lines and points,
 * the globals, and the indexes the checks look near an action in: a DiscGrid of the bodies of known
 * position, and the lines and points by place (sim/obstacleCells.ts, built once a few discs have
 * checked). A lazy view reads its bodies only when an action needs them all.
 */
import { ObstacleCells } from "../sim/obstacleCells.js";
import { DiscGrid } from "./discGrid.js";
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

/** A state whose bodies are read only when an action needs them all (SceneView.lazy). */
export interface LazyViewSource extends Omit<ViewSource, "bodies"> {
  bodies(): ViewSource["bodies"];
  hasBody(id: string): boolean;
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
  /** Of a lazy view, the source its bodies are read from (null once they are), and the ids removed
   *  meanwhile. */
  private source: LazyViewSource | null = null;
  private removed: Set<string> | null = null;

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
   * bodies for each such group made a scene's later actions cost seconds each). Until then `s`
   * must give the state at the view's time less the bodies this view removed (a World the group's
   * actions are applied to as they are checked does).
   */
  static lazy(s: LazyViewSource): SceneView {
    const v = SceneView.of({ ...s, bodies: [] });
    v.source = s;
    return v;
  }

  private addBodies(bodies: ViewSource["bodies"]): void {
    for (const b of bodies) {
      if (this.removed?.has(b.id)) continue;
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
      this.removed = null;
    }
    return this.bodyMap;
  }

  /** The discs of the bodies whose position is known. */
  get grid(): DiscGrid {
    if (this.source !== null) void this.bodies;
    return this.discs;
  }

  /** Whether body `id` is in the view (without reading a lazy view's bodies). */
  hasBody(id: string): boolean {
    if (this.source === null) return this.bodyMap.has(id);
    return this.removed?.has(id) !== true && this.source.hasBody(id);
  }

  /** Removes body `id` (in the view: `hasBody(id)`). */
  removeBody(id: string): void {
    if (this.source === null) {
      this.bodyMap.delete(id);
      this.discs.remove(id);
    } else {
      this.removed ??= new Set();
      this.removed.add(id);
    }
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
