/**
 * The World's obstacles as the user edits them: add, update, remove and list lines (line, ray,
 * segment) and points, at the current time. Each edit is checked first by placement.ts (its input,
 * and no overlap with a body: touching is allowed) and throws ChapgameError naming the field before
 * anything changes; what a checked edit then does to the lists, the grid and the predictions is
 * obstacleUpkeep.ts's. Ids are unique per kind; `lines()` and `points()` list them sorted by id.
 */
import { ChapgameError } from "./errors.js";
import type { LineKind, Point } from "./obstacles.js";
import { Placement } from "./placement.js";
import { quoteId } from "./refusalText.js";
import type { LineState, PointState, Vec2 } from "./types.js";
import { requireFields, requireId } from "./validate.js";

export class ObstacleEdits extends Placement {
  /** Whether a line (of any kind: line, ray or segment) with this id exists. */
  hasLine(id: string): boolean {
    return this.lineAt.has(this.lineList, id);
  }

  /** Whether a point obstacle with this id exists. */
  hasPoint(id: string): boolean {
    return this.pointAt.has(this.pointList, id);
  }

  /**
   * Add a line obstacle at the current time: `kind` "line" (infinite, through p1 and p2), "ray"
   * (from p1 through p2) or "segment" (p1 to p2). It may touch a disc but not cut into one. Throws
   * ChapgameError naming `id` (empty, or taken by a line), `p1` or `p2` (not a pair [x, y]; `p1[1]`
   * for a coordinate that is not finite or exceeds 1e30 in size), `p2` equal to p1, `p1` for an
   * overlap with a body, or `kind`. Nothing changes on error.
   */
  addLine(id: string, p1: Vec2, p2: Vec2, kind: LineKind): void {
    requireId("id", id);
    if (this.hasLine(id)) throw new ChapgameError("id", `a line with id ${quoteId(id)} already exists`);
    const line = this.checkedLine(id, p1, p2, kind);
    this.addLineEntry(line);
    this.placedLine(line);
  }

  /**
   * Move a line or change its kind at the current time (fields left out are kept; a LineState's
   * `id` is accepted and ignored). Checked as addLine, except that an overlap with a body names the
   * field that changed (`p1`, else `p2`, else `kind`); ChapgameError naming `id` when there is no
   * such line. Nothing changes on error.
   */
  updateLine(id: string, patch: { p1?: Vec2; p2?: Vec2; kind?: LineKind }): void {
    requireId("id", id);
    const old = this.lineAt.get(this.lineList, id);
    if (old === undefined) throw new ChapgameError("id", `no line with id ${quoteId(id)}`);
    // (a LineState's id may come back with it; the id argument names the line)
    requireFields("patch", patch, ["p1", "p2", "kind"], ["id"]);
    const p1 = patch.p1 ?? [old.x1, old.y1];
    const p2 = patch.p2 ?? [old.x2, old.y2];
    const kind = patch.kind ?? old.kind;
    // Name the field that changed (a LineState passed back whole gives every key).
    const moved = (p: Vec2, x: number, y: number) => p[0] !== x || p[1] !== y;
    const field = moved(p1, old.x1, old.y1)
      ? "p1"
      : moved(p2, old.x2, old.y2)
        ? "p2"
        : kind !== old.kind
          ? "kind"
          : "p1";
    const end = moved(p1, old.x1, old.y1) && !moved(p2, old.x2, old.y2) ? "p1" : "p2";
    const line = this.checkedLine(id, p1, p2, kind, field, end);
    this.replaceLineEntry(line);
    this.placedLine(line);
  }

  /** Remove a line at the current time. Throws ChapgameError naming `id` when there is no such line. */
  removeLine(id: string): void {
    requireId("id", id);
    if (!this.hasLine(id)) throw new ChapgameError("id", `no line with id ${quoteId(id)}`);
    this.removeLineEntry(id);
    this.removedLine(id);
  }

  /**
   * Add a point obstacle at `p` at the current time; it may lie on a disc's rim, not inside a disc.
   * Throws ChapgameError naming `id` (empty, or taken by a point), `p` (not a pair [x, y], or inside
   * a body) or a coordinate (`p[0]`: not finite, or over 1e30 in size).
   */
  addPoint(id: string, p: Vec2): void {
    requireId("id", id);
    if (this.hasPoint(id)) throw new ChapgameError("id", `a point with id ${quoteId(id)} already exists`);
    this.placePoint(this.checkedPoint(id, p), false);
  }

  /** Move a point to `p` at the current time. Checked as addPoint; ChapgameError naming `id` when there is no such point. */
  updatePoint(id: string, p: Vec2): void {
    requireId("id", id);
    if (!this.hasPoint(id)) throw new ChapgameError("id", `no point with id ${quoteId(id)}`);
    this.placePoint(this.checkedPoint(id, p), true);
  }

  /** Remove a point at the current time. Throws ChapgameError naming `id` when there is no such point. */
  removePoint(id: string): void {
    requireId("id", id);
    if (!this.hasPoint(id)) throw new ChapgameError("id", `no point with id ${quoteId(id)}`);
    this.removePointEntry(id);
    this.removedPoint(id);
  }

  /** Store a checked point, new or in place of the one of its id. */
  private placePoint(point: Point, replace: boolean): void {
    if (replace) this.replacePointEntry(point);
    else this.addPointEntry(point);
    this.placedPoint(point);
  }

  /** All lines, sorted by id. */
  lines(): LineState[] {
    this.compactObstacles();
    return [...this.lineList]
      .sort((a, b) => (a.id < b.id ? -1 : 1))
      .map((l) => ({ id: l.id, p1: [l.x1, l.y1] as Vec2, p2: [l.x2, l.y2] as Vec2, kind: l.kind }));
  }

  /** All points, sorted by id. */
  points(): PointState[] {
    this.compactObstacles();
    return [...this.pointList]
      .sort((a, b) => (a.id < b.id ? -1 : 1))
      .map((p) => ({ id: p.id, p: [p.x, p.y] as Vec2 }));
  }
}
