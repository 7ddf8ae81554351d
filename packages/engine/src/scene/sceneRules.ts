/**
 * The rules an action must satisfy against the scene as it is at the action's time: ids that exist
 * (or not yet), unique ids among live objects of a kind, no body added, moved or grown into an overlap
 * with a body, line or point, no line or point added or moved into a body, and no friction (mu > 0)
 * together with a non-zero gravity field. `SceneView` (sceneView.ts) is that scene (positions may be
 * unknown when a caller cannot simulate: then overlaps with such bodies are not checked). `checkAndApply` throws
 * SceneError (path + reason) and changes nothing, or updates the view. Overlaps are looked for near
 * the action (a disc among the segments and points near it, sim/obstacleCells.ts; a segment or point
 * among the discs near it, discGrid.ts), infinite lines and rays against everything; each refusal
 * names the smallest id hit, as a scan of everything would.
 */
import { frictionUnderGravity, gravityWithFriction, quoteId } from "../sim/refusalText.js";
import { SceneError } from "./errors.js";
import { join } from "./fields.js";
import { lineDirection } from "./magnitudes.js";
import { discOverlapsLine, discOverlapsPoint } from "./overlap.js";
import type { SceneView, ViewBody, ViewLine } from "./sceneView.js";
import type { Action, Vec2 } from "./types.js";

export {
  type LazyViewSource,
  SceneView,
  type ViewBody,
  type ViewLine,
  type ViewSource,
} from "./sceneView.js";

/** An id as every refusal quotes it (sim/refusalText.ts). */
const q = quoteId;

function gravityOn(g: Vec2): boolean {
  return g[0] !== 0 || g[1] !== 0;
}

function frictionWithGravity(path: string, mu: number): SceneError {
  return new SceneError(path, frictionUnderGravity(mu));
}

function checkDisc(view: SceneView, path: string, id: string, x: number, y: number, r: number): void {
  const other = view.overlapOf(x, y, r, id);
  if (other !== null)
    throw new SceneError(path, `body ${q(id)} would overlap body ${q(other)} at time ${view.time}`);
  // The smallest id hit, as the World names it: the message does not depend on the order of adds.
  const cells = view.obstacleCells();
  const hitsLine = (l: ViewLine) => discOverlapsLine(x, y, r, l.p1, l.p2, l.kind);
  const line = cells === null ? smallestHit(view.lines, hitsLine) : cells[0].smallestHit(x, y, r, hitsLine);
  if (line !== undefined)
    throw new SceneError(path, `body ${q(id)} would overlap line ${q(line)} at time ${view.time}`);
  const hitsPoint = (p: Vec2) => discOverlapsPoint(x, y, r, p);
  const point =
    cells === null ? smallestHit(view.points, hitsPoint) : cells[1].smallestHit(x, y, r, hitsPoint);
  if (point !== undefined)
    throw new SceneError(path, `body ${q(id)} would overlap point ${q(point)} at time ${view.time}`);
}

/** The smallest id of `map` whose value `hits`, if any (one pass). */
function smallestHit<T>(map: Map<string, T>, hits: (v: T) => boolean): string | undefined {
  let first: string | undefined;
  for (const [key, v] of map) if ((first === undefined || key < first) && hits(v)) first = key;
  return first;
}

/**
 * Refuses an obstacle that `hits` a body of known position (x, y, r), naming the smallest such id:
 * among the discs near `near` (a segment, or a point: both ends equal; the view's grid holds the
 * bodies of known position), else (an infinite line or ray) among all (one pass: sorting every
 * body's id for each line added made a scene of n bodies and m lines cost m n log n).
 */
function checkObstacle(
  view: SceneView,
  path: string,
  what: string,
  hits: (x: number, y: number, r: number) => boolean,
  near: readonly [Vec2, Vec2] | null,
): void {
  const first =
    near === null
      ? smallestHit(view.bodies, (b) => b.known && hits(b.x, b.y, b.r))
      : (view.smallestNearSegment(near[0][0], near[0][1], near[1][0], near[1][1], hits) ?? undefined);
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

function exists(id: string, kind: string, view: SceneView, path: string): SceneError {
  return new SceneError(join(path, "id"), `${kind} ${q(id)} already exists at time ${view.time}`);
}

function fresh(map: Map<string, unknown>, id: string, kind: string, view: SceneView, path: string): void {
  if (map.has(id)) throw exists(id, kind, view, path);
}

/** Checks `a` (already field-validated) against the view at its time, then applies it to the view. */
export function checkAndApply(view: SceneView, a: Action, path: string): void {
  switch (a.type) {
    case "addBody": {
      if (view.hasBody(a.id)) throw exists(a.id, "body", view, path);
      const mu = a.mu ?? 0;
      if (mu > 0 && gravityOn(view.gravity)) throw frictionWithGravity(join(path, "mu"), mu);
      checkDisc(view, path, a.id, a.x, a.y, a.r);
      view.setBody(a.id, { x: a.x, y: a.y, r: a.r, mu, known: true });
      return;
    }
    case "giveVelocity":
      if (!view.hasBody(a.id)) throw missing(a.id, "body", view, path);
      return;
    case "updateBody": {
      const b = view.body(a.id);
      if (b === undefined) throw missing(a.id, "body", view, path);
      const mu = a.mu ?? b.mu;
      if (a.mu !== undefined && mu > 0 && gravityOn(view.gravity))
        throw frictionWithGravity(join(path, "mu"), mu);
      const known = b.known || (a.x !== undefined && a.y !== undefined);
      const x = a.x ?? b.x;
      const y = a.y ?? b.y;
      const r = a.r ?? b.r;
      const moved = a.x !== undefined || a.y !== undefined || a.r !== undefined;
      if (known && moved) checkDisc(view, path, a.id, x, y, r);
      view.setBody(a.id, { x, y, r, mu, known });
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
        lineDirection(join(path, a.p2 ? "p2" : "p1"), line.p1, line.p2, a.p2 ? "p1" : "p2");
      }
      checkObstacle(
        view,
        path,
        `line ${q(a.id)}`,
        (x, y, r) => discOverlapsLine(x, y, r, line.p1, line.p2, line.kind),
        line.kind === "segment" ? [line.p1, line.p2] : null,
      );
      view.setLine(a.id, line);
      return;
    }
    case "removeLine":
      need(view.lines, a.id, "line", view, path);
      view.deleteLine(a.id);
      return;
    case "addPoint":
    case "updatePoint": {
      if (a.type === "addPoint") fresh(view.points, a.id, "point", view, path);
      else need(view.points, a.id, "point", view, path);
      const p = a.p;
      checkObstacle(view, path, `point ${q(a.id)}`, (x, y, r) => discOverlapsPoint(x, y, r, p), [p, p]);
      view.setPoint(a.id, p);
      return;
    }
    case "removePoint":
      need(view.points, a.id, "point", view, path);
      view.deletePoint(a.id);
      return;
    case "setGlobal": {
      const gravity = a.gravity ?? view.gravity;
      if (a.gravity !== undefined && gravityOn(gravity)) {
        // every body with friction, not only the first (audit of session 20: one refusal per body)
        const ids = [...view.bodies.keys()].sort().filter((bid) => (view.bodies.get(bid) as ViewBody).mu > 0);
        if (ids.length > 0) throw new SceneError(join(path, "gravity"), gravityWithFriction(ids));
      }
      if (a.g !== undefined) view.g = a.g;
      view.gravity = gravity;
      return;
    }
  }
}
