/**
 * The rules an action must satisfy against the scene as it is at the action's time: ids that exist
 * (or not yet), unique ids among live objects of a kind, no body added, moved or grown into an overlap
 * with a body, line or point, no line or point added or moved into a body, and no friction (mu > 0)
 * together with a non-zero gravity field. `SceneView` is that scene (positions may be unknown when a
 * caller cannot simulate: then overlaps with such bodies are not checked). `checkAndApply` throws
 * SceneError (path + reason) and changes nothing, or updates the view.
 */
import { quoteId } from "../sim/refusalText.js";
import { DiscGrid } from "./discGrid.js";
import { SceneError } from "./errors.js";
import { join } from "./fields.js";
import { lineDirection } from "./magnitudes.js";
import { discOverlapsLine, discOverlapsPoint } from "./overlap.js";
import type { Action, LineKind, Vec2 } from "./types.js";

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

  /** Time moves on without a simulation: every body's position becomes unknown. */
  forgetPositions(time: number): void {
    this.time = time;
    for (const b of this.bodies.values()) b.known = false;
    this.discs.clear();
  }
}

/** An id as every refusal quotes it (sim/refusalText.ts). */
const q = quoteId;

function gravityOn(g: Vec2): boolean {
  return g[0] !== 0 || g[1] !== 0;
}

function frictionWithGravity(path: string): SceneError {
  return new SceneError(path, "friction (mu > 0) cannot be combined with a non-zero gravity field");
}

function checkDisc(view: SceneView, path: string, id: string, x: number, y: number, r: number): void {
  const other = view.grid.findOverlap(x, y, r, id);
  if (other !== null)
    throw new SceneError(path, `body ${q(id)} would overlap body ${q(other)} at time ${view.time}`);
  // The smallest id hit, as the World names it: the message does not depend on the order of adds.
  const line = smallestHit(view.lines, (l) => discOverlapsLine(x, y, r, l.p1, l.p2, l.kind));
  if (line !== undefined)
    throw new SceneError(path, `body ${q(id)} would overlap line ${q(line)} at time ${view.time}`);
  const point = smallestHit(view.points, (p) => discOverlapsPoint(x, y, r, p));
  if (point !== undefined)
    throw new SceneError(path, `body ${q(id)} would overlap point ${q(point)} at time ${view.time}`);
}

/** The smallest id of `map` whose value `hits`, if any (one pass). */
function smallestHit<T>(map: Map<string, T>, hits: (v: T) => boolean): string | undefined {
  let first: string | undefined;
  for (const [key, v] of map) if ((first === undefined || key < first) && hits(v)) first = key;
  return first;
}

/** Refuses an obstacle that `hits` a body of known position, naming the smallest such id (one pass:
 *  sorting every body's id for each line added made a scene of n bodies and m lines cost m n log n). */
function checkObstacle(view: SceneView, path: string, what: string, hits: (b: ViewBody) => boolean): void {
  const first = smallestHit(view.bodies, (b) => b.known && hits(b));
  if (first !== undefined)
    throw new SceneError(path, `${what} would overlap body ${q(first)} at time ${view.time}`);
}

function missing(id: string, kind: string, view: SceneView, path: string): SceneError {
  return new SceneError(join(path, "id"), `no ${kind} ${q(id)} at time ${view.time}`);
}

function need<T>(map: Map<string, T>, id: string, kind: string, view: SceneView, path: string): T {
  const v = map.get(id);
  if (v === undefined) throw missing(id, kind, view, path);
  return v;
}

function fresh(map: Map<string, unknown>, id: string, kind: string, view: SceneView, path: string): void {
  if (map.has(id))
    throw new SceneError(join(path, "id"), `${kind} ${q(id)} already exists at time ${view.time}`);
}

/** Checks `a` (already field-validated) against the view at its time, then applies it to the view. */
export function checkAndApply(view: SceneView, a: Action, path: string): void {
  switch (a.type) {
    case "addBody": {
      fresh(view.bodies, a.id, "body", view, path);
      const mu = a.mu ?? 0;
      if (mu > 0 && gravityOn(view.gravity)) throw frictionWithGravity(join(path, "mu"));
      checkDisc(view, path, a.id, a.x, a.y, a.r);
      view.bodies.set(a.id, { x: a.x, y: a.y, r: a.r, mu, known: true });
      view.grid.add(a.id, a.x, a.y, a.r); // a new body: the grid holds only the view's bodies
      return;
    }
    case "giveVelocity":
      if (!view.hasBody(a.id)) throw missing(a.id, "body", view, path);
      return;
    case "updateBody": {
      const b = need(view.bodies, a.id, "body", view, path);
      const mu = a.mu ?? b.mu;
      if (a.mu !== undefined && mu > 0 && gravityOn(view.gravity))
        throw frictionWithGravity(join(path, "mu"));
      const known = b.known || (a.x !== undefined && a.y !== undefined);
      const x = a.x ?? b.x;
      const y = a.y ?? b.y;
      const r = a.r ?? b.r;
      const moved = a.x !== undefined || a.y !== undefined || a.r !== undefined;
      if (known && moved) checkDisc(view, path, a.id, x, y, r);
      view.bodies.set(a.id, { x, y, r, mu, known });
      if (known) view.grid.insert(a.id, x, y, r);
      return;
    }
    case "removeBody":
      if (!view.hasBody(a.id)) throw missing(a.id, "body", view, path);
      view.removeBody(a.id);
      return;
    case "addLine":
    case "updateLine": {
      let line: ViewLine;
      if (a.type === "addLine") {
        fresh(view.lines, a.id, "line", view, path);
        line = { p1: a.p1, p2: a.p2, kind: a.kind };
      } else {
        const old = need(view.lines, a.id, "line", view, path);
        line = { p1: a.p1 ?? old.p1, p2: a.p2 ?? old.p2, kind: a.kind ?? old.kind };
        lineDirection(join(path, a.p2 ? "p2" : "p1"), line.p1, line.p2, "p1 and p2 of the line");
      }
      checkObstacle(view, path, `line ${q(a.id)}`, (b) =>
        discOverlapsLine(b.x, b.y, b.r, line.p1, line.p2, line.kind),
      );
      view.lines.set(a.id, line);
      return;
    }
    case "removeLine":
      need(view.lines, a.id, "line", view, path);
      view.lines.delete(a.id);
      return;
    case "addPoint":
    case "updatePoint": {
      if (a.type === "addPoint") fresh(view.points, a.id, "point", view, path);
      else need(view.points, a.id, "point", view, path);
      const p = a.p;
      checkObstacle(view, path, `point ${q(a.id)}`, (b) => discOverlapsPoint(b.x, b.y, b.r, p));
      view.points.set(a.id, p);
      return;
    }
    case "removePoint":
      need(view.points, a.id, "point", view, path);
      view.points.delete(a.id);
      return;
    case "setGlobal": {
      const gravity = a.gravity ?? view.gravity;
      if (a.gravity !== undefined && gravityOn(gravity)) {
        // every body with friction, not only the first (audit of session 20: one refusal per body)
        const ids = [...view.bodies.keys()].sort().filter((bid) => (view.bodies.get(bid) as ViewBody).mu > 0);
        if (ids.length > 0) {
          const shown = ids
            .slice(0, 10)
            .map((bid) => q(bid))
            .join(", ");
          const more = ids.length > 10 ? ` and ${ids.length - 10} more` : "";
          const which =
            ids.length === 1
              ? `body ${shown} has mu > 0: set its mu to 0 first`
              : `bodies ${shown}${more} have mu > 0: set their mu to 0 first`;
          throw new SceneError(
            join(path, "gravity"),
            `a non-zero gravity field cannot be combined with friction (${which})`,
          );
        }
      }
      if (a.g !== undefined) view.g = a.g;
      view.gravity = gravity;
      return;
    }
  }
}
