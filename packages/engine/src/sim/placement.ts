/**
 * The placement checks for every edit: whether a disc, line or point may be put somewhere without
 * overlapping what is already there (touching is allowed); the edits that call them are
 * obstacleEdits.ts's (lines and points) and edits.ts's (discs). A disc is tested against the bodies
 * near it in the broad-phase grid and the segments and points near it in ObstacleCells
 * (obstacleCells.ts); a segment or point against the bodies near it in the grid (bodiesNear.ts);
 * infinite lines and rays, few, are tested against every body, and every disc against all of them.
 * Each check names the smallest id it hits, as a scan of everything would. Every check throws
 * ChapgameError naming the field before anything changes. The index by place of the lines and
 * points (ObstacleCells) is built on the first disc check and kept in step by the obstacle edits
 * (placedLine, removedLine, placedPoint, removedPoint). What a checked obstacle edit does to the
 * lists, the grid and the predictions: obstacleUpkeep.ts. The same candidates serve the scene
 * rules' checks of a Timeline's actions (forEachBodyNear, forEachBodyNearSegment:
 * scene/sceneView.ts), which test them with the scene's own rounding.
 */
import { OVERLAP_REL } from "../tolerances.js";
import { forEachBodyNearSegment } from "./bodiesNear.js";
import { stateOf } from "./bodyState.js";
import { ChapgameError } from "./errors.js";
import { ObstacleCells } from "./obstacleCells.js";
import { distanceToLine, type Line, type LineKind, makeLine, type Point } from "./obstacles.js";
import { ObstacleUpkeep } from "./obstacleUpkeep.js";
import { quoteId } from "./refusalText.js";
import type { Vec2 } from "./types.js";
import { requireLineDirection, requireLineKind, requireVec } from "./validate.js";

/** Contact distances are shortened by this factor before testing an overlap (OVERLAP_REL's slack). */
const KEEP = 1 - OVERLAP_REL;

/** A body's id, position now and radius, to a scene rule (forEachBodyNear). */
type DiscVisit = (id: string, x: number, y: number, r: number) => void;

/** Below this many bodies an overlap check scans them all instead of using the grid. */
const LINEAR_SCAN_BODIES = 64;

export class Placement extends ObstacleUpkeep {
  /** @internal Slot of each body id (not in the shipped types: its Map would ask a consumer's
   *  compiler for lib es2015, and it is the World's own bookkeeping, not an API). */
  protected index = new Map<string, number>();
  /** The lines and the points by place, built when a disc is first checked (a copy starts without). */
  private lineCells: ObstacleCells<Line> | null = null;
  private pointCells: ObstacleCells<Point> | null = null;

  /** A checked line; an overlap with a body is refused naming `field` (addLine: p1; updateLine:
   *  the first of p1, p2, kind that changed), ends too close naming `end` (p2, or p1 when only p1
   *  moved: "p1: must differ from p2"). */
  protected checkedLine(id: string, p1: Vec2, p2: Vec2, kind: LineKind, field = "p1", end = "p2"): Line {
    const a = requireVec("p1", p1);
    const c = requireVec("p2", p2);
    requireLineKind("kind", kind);
    requireLineDirection(end, a, c, end === "p1" ? "p2" : "p1");
    const line = makeLine(id, a, c, kind);
    const hit = this.firstBodyWhere(
      (s) =>
        distanceToLine(line, this.xAt(s, this.now), this.yAt(s, this.now)) <
        (this.store.r[s] as number) * KEEP,
      kind === "segment" ? line : undefined,
    );
    if (hit !== undefined) throw new ChapgameError(field, `the line would overlap body ${quoteId(hit)}`);
    return line;
  }

  protected checkedPoint(id: string, p: Vec2): Point {
    const [x, y] = requireVec("p", p);
    const hit = this.firstBodyWhere(
      (s) => {
        const dx = this.xAt(s, this.now) - x;
        const dy = this.yAt(s, this.now) - y;
        const r = (this.store.r[s] as number) * KEEP;
        return dx * dx + dy * dy < r * r;
      },
      { x1: x, y1: y, x2: x, y2: y },
    );
    if (hit !== undefined) throw new ChapgameError("p", `the point would lie inside body ${quoteId(hit)}`);
    return { id, x, y };
  }

  /**
   * The smallest id of the bodies for which `test` holds (a message independent of insertion order):
   * among those near `near` (a segment, or a point: both ends equal) when the grid holds enough
   * bodies, else among all (an infinite line or ray, a small scene).
   */
  private firstBodyWhere(
    test: (s: number) => boolean,
    near?: { x1: number; y1: number; x2: number; y2: number },
  ): string | undefined {
    let best: string | undefined;
    if (near === undefined || this.index.size < LINEAR_SCAN_BODIES) {
      for (const [bid, s] of this.index) if ((best === undefined || bid < best) && test(s)) best = bid;
      return best;
    }
    const ids = this.store.ids;
    forEachBodyNearSegment(this.grid, near.x1, near.y1, near.x2, near.y2, (s) => {
      const bid = ids[s] as string;
      if ((best === undefined || bid < best) && test(s)) best = bid;
    });
    return best;
  }

  /**
   * @internal For the scene rules (scene/sceneView.ts): `visit(id, x, y, r)` for every body that
   * could overlap the disc (x, y, r) now, and perhaps others, each at its position now as `body(id)`
   * gives it: the candidates checkOverlap tests (the bodies near it in the grid, or all of a small
   * scene), so that checking a disc added to n bodies costs about O(1), not O(n).
   */
  forEachBodyNear(x: number, y: number, r: number, visit: DiscVisit): void {
    const at = this.stateVisitor(visit);
    if (this.index.size < LINEAR_SCAN_BODIES) for (const s of this.index.values()) at(s);
    else this.forEachNear(x, y, r, at);
  }

  /**
   * @internal forEachBodyNear for the segment (x1, y1)-(x2, y2) (a point when both ends are equal):
   * every body that could overlap it, and perhaps others (the candidates of checkedLine and
   * checkedPoint).
   */
  forEachBodyNearSegment(x1: number, y1: number, x2: number, y2: number, visit: DiscVisit): void {
    const at = this.stateVisitor(visit);
    if (this.index.size < LINEAR_SCAN_BODIES) for (const s of this.index.values()) at(s);
    else forEachBodyNearSegment(this.grid, x1, y1, x2, y2, at);
  }

  /** A visitor of slots calling `visit` with each one's id, position now and radius. */
  private stateVisitor(visit: DiscVisit): (s: number) => void {
    return (s) => {
      const b = stateOf(this.store, s, this.now);
      visit(b.id, b.x, b.y, b.r);
    };
  }

  /** The lines and the points indexed by place (built from the lists when first needed). */
  private obstacleCells(): [ObstacleCells<Line>, ObstacleCells<Point>] {
    if (this.lineCells === null || this.pointCells === null) {
      this.compactObstacles();
      this.lineCells = new ObstacleCells<Line>();
      this.pointCells = new ObstacleCells<Point>();
      for (const l of this.lineList) indexLine(this.lineCells, l);
      for (const p of this.pointList) this.pointCells.set(p.id, p, p.x, p.y, p.x, p.y, true);
    }
    return [this.lineCells, this.pointCells];
  }

  /**
   * Rebuild the grid (roomier) when a disc (x, y, r) lands outside it in a large scene, or when the
   * bodies have doubled since its cells were sized: the edge cells extend to infinity and every cell
   * takes any number of bodies, so the grid stays right, but crowded cells are slow. Discs added at
   * random spots inside the first few's region never left it, the grid sized for 64 bodies held
   * 10^5, and each placement check scanned thousands (10^5 additions took 24 s). Doubling keeps
   * the rebuilds at O(log n), O(n) in all. Any radius has a level (the top one is a single cell).
   */
  protected prepareGridFor(x: number, y: number, r: number): void {
    if (this.index.size < LINEAR_SCAN_BODIES) return;
    const g = this.grid;
    const inside = x >= g.ox && x <= g.ox + g.nx * g.w && y >= g.oy && y <= g.oy + g.ny * g.w;
    if (!inside || this.index.size + 1 > 2 * this.gridBodies) this.rebuildGrid(x, y, r, 2);
  }

  /**
   * Throw if a disc (x, y, r) would overlap any body (other than slot `self`), line or point by more
   * than OVERLAP_REL of the contact distance: touching is allowed, with the round-off of its
   * coordinates (discs packed at distances like sqrt(3) touch only to the last digit) and the
   * round-off the engine's own collisions leave between bodies in contact; the scene file's check
   * (scene/overlap.ts) uses the same slack. The error names `field`: the edited field that made the
   * overlap (an update that only grows r names r).
   */
  protected checkOverlap(x: number, y: number, r: number, self: number, field: "x" | "y" | "r" = "x"): void {
    const b = this.store;
    const now = this.now;
    const keep = KEEP;
    // Every overlap is found and the smallest id named, so the message does not depend on the
    // order bodies were added in or on the broad phase's scan order.
    let body: string | undefined;
    const test = (s: number): void => {
      if (s === self) return;
      const dx = this.xAt(s, now) - x;
      const dy = this.yAt(s, now) - y;
      const R = (r + (b.r[s] as number)) * keep;
      const id = b.ids[s] as string;
      if (dx * dx + dy * dy < R * R && (body === undefined || id < body)) body = id;
    };
    if (this.index.size < LINEAR_SCAN_BODIES) {
      for (const s of this.index.values()) test(s);
    } else this.forEachNear(x, y, r, test);
    if (body !== undefined) throw new ChapgameError(field, `the body would overlap body ${quoteId(body)}`);
    const rk = r * keep;
    const [lines, points] = this.obstacleCells();
    const line = lines.smallestHit(x, y, r, (l) => distanceToLine(l, x, y) < rk);
    if (line !== undefined) throw new ChapgameError(field, `the body would overlap line ${quoteId(line)}`);
    const point = points.smallestHit(x, y, r, (p) => (p.x - x) * (p.x - x) + (p.y - y) * (p.y - y) < rk * rk);
    if (point !== undefined) throw new ChapgameError(field, `the body would overlap point ${quoteId(point)}`);
  }

  // ---- the index by place, kept in step with the obstacle edits (obstacleEdits.ts) --------------

  /** A line added or moved: put in the index by place, when it is built. */
  protected placedLine(line: Line): void {
    if (this.lineCells !== null) indexLine(this.lineCells, line);
  }

  /** A line removed: out of the index by place, when it is built. */
  protected removedLine(id: string): void {
    this.lineCells?.delete(id);
  }

  /** A point added or moved: put in the index by place, when it is built. */
  protected placedPoint(point: Point): void {
    this.pointCells?.set(point.id, point, point.x, point.y, point.x, point.y, true);
  }

  /** A point removed: out of the index by place, when it is built. */
  protected removedPoint(id: string): void {
    this.pointCells?.delete(id);
  }
}

/** Put `line` in `cells` (a segment by place; a line or ray is tested by every query). */
function indexLine(cells: ObstacleCells<Line>, line: Line): void {
  cells.set(line.id, line, line.x1, line.y1, line.x2, line.y2, line.kind === "segment");
}
