/**
 * What an edit of a line or point does to the World's lists, its grid and its predictions
 * (obstacleEdits.ts calls these once placement.ts has checked the edit).
 *
 * While the predictions are up to date and the grid can keep its layout, the edit is local: a
 * segment or point is registered in, or taken out of, the cells it covers (gridObstacleEdits.ts), and
 * only the bodies whose predictions can change are predicted again: the moving bodies whose 3x3
 * scan covers a cell the obstacle enters (a body elsewhere meets it only after crossing into such a
 * cell, and a crossing scans the cells it brings: the rows already hold the obstacle), and every body
 * whose queued event is with the obstacle moved or removed. The rest keep their predictions: each
 * is the earliest of candidates that are pure functions of the motions (architecture.md), which
 * the edit did not touch. So the events are those of a full rebuild, bit for bit
 * (obstacleUpkeep.prop.test.ts compares the two), and an edit costs the cells it covers, the bodies
 * near them, and a pass over the bodies' queued events when an obstacle is moved or removed (two
 * integer reads per body, no prediction), not a prediction of every body. A removal closes the
 * gap in its list at once (the lists keep the order of the adds, obstacleIndex.ts) and renumbers
 * what refers to the positions after it: the grid's rows, the infinite lines, the queued events.
 *
 * Otherwise the edit marks the predictions out of date, and the next advance lays the grid out
 * again and predicts every body: when they are out of date already (before the first advance,
 * after a change of globals), when an infinite line or ray is added or moved (every moving body
 * tests it), and when the segments and points leave the range the layout was computed for
 * (GRID_OBSTACLE_RELAYOUT: their count doubled or halved) and the cost estimate that chose the
 * layout (broadPhase.ts, gridCost.ts) now chooses another: the other kind (sized by the bodies, or
 * by the obstacles), or cells more than GRID_OBSTACLE_RELAYOUT times larger or smaller (when it
 * chooses the same, the range starts again from there). A stream of m edits so evaluates the
 * estimate O(log m) times, and lays the grid out again at most as often.
 *
 * Measured (24 Nov 2026, shared 2-core host, a scratch script through World: moving discs of
 * radius 1 on a lattice, 1,000 wall segments around them and 1,000 points added one per edit,
 * then each moved, then each removed, 3 events advanced between edits; times noisy): with 5,000
 * discs, every 1,000 edits cost 5.0 million predictions and 3.4–9.9 s before (every edit marked the
 * predictions out of date), and after 6,400–8,400 predictions and 0.13–0.38 s, of which the 3
 * events between edits alone make 6,300 predictions and 0.18–0.25 s (about 1–2 predictions per
 * add or move, 0.1 per removal; no re-layout: the estimate kept the body layout each time it was
 * asked). With 20,000 discs: 20,000 predictions and 15–28 ms per edit before, 0.2–0.6 s per
 * 1,000 edits after. The same events and final state, bit for bit.
 */
import { GRID_MIN_BODIES, GRID_OBSTACLE_RELAYOUT } from "../tolerances.js";
import { EV_LINE, EV_POINT } from "./bodyStore.js";
import { addObstacle, removeObstacle, renumberAfterRemoval } from "./gridObstacleEdits.js";
import type { Line, Point } from "./obstacles.js";
import { Simulator } from "./simulator.js";
import type { SimState } from "./state.js";

const INF = Number.POSITIVE_INFINITY;

export class ObstacleUpkeep extends Simulator {
  /**
   * @internal Tests only: every obstacle edit marks the predictions out of date, as before edits
   * were local (the full rebuild the local path is compared with).
   */
  protected fullObstacleRebuild = false;

  protected override copyInto(target: SimState): void {
    super.copyInto(target);
    (target as ObstacleUpkeep).fullObstacleRebuild = this.fullObstacleRebuild;
  }

  /** Append a checked line to the list. */
  protected addLineEntry(line: Line): void {
    const local = line.kind === "segment" && this.keepsLayout(1);
    const i = this.lineList.length;
    this.lineAt.add(this.lineList, line);
    if (!local) {
      this.markDirty();
      return;
    }
    const cells = this.cellsOfObstacle(line.x1, line.y1, line.x2, line.y2);
    addObstacle(this.grid, i, cells);
    this.repredict(cells, EV_LINE, -1);
  }

  /** Put a checked line in the place of the line of its id. */
  protected replaceLineEntry(line: Line): void {
    const old = this.lineAt.get(this.lineList, line.id) as Line;
    const i = this.lineAt.indexOf(this.lineList, line.id);
    const local = line.kind === "segment" && this.keepsLayout(old.kind === "segment" ? 0 : 1);
    this.lineAt.replace(this.lineList, line);
    if (!local) {
      this.markDirty();
      return;
    }
    if (old.kind === "segment")
      removeObstacle(this.grid, i, this.cellsOfObstacle(old.x1, old.y1, old.x2, old.y2));
    else this.globalLines = this.globalLines.filter((j) => j !== i);
    const cells = this.cellsOfObstacle(line.x1, line.y1, line.x2, line.y2);
    addObstacle(this.grid, i, cells);
    this.repredict(cells, EV_LINE, i);
  }

  /** Remove the line `id` (which is in the list). */
  protected removeLineEntry(id: string): void {
    const i = this.lineAt.indexOf(this.lineList, id);
    const old = this.lineList[i] as Line;
    const local = this.keepsLayout(old.kind === "segment" ? -1 : 0);
    this.lineAt.remove(this.lineList, id);
    if (!local) {
      this.markDirty();
      return;
    }
    if (old.kind === "segment")
      removeObstacle(this.grid, i, this.cellsOfObstacle(old.x1, old.y1, old.x2, old.y2));
    this.lineAt.compact(this.lineList);
    renumberAfterRemoval(this.grid, i);
    this.globalLines = this.globalLines.filter((j) => j !== i).map((j) => (j > i ? j - 1 : j));
    this.repredict([], EV_LINE, i, true);
  }

  /** Append a checked point to the list. */
  protected addPointEntry(point: Point): void {
    const local = this.keepsLayout(1);
    const i = this.pointList.length;
    this.pointAt.add(this.pointList, point);
    if (!local) {
      this.markDirty();
      return;
    }
    const cells = this.cellsOfObstacle(point.x, point.y, point.x, point.y);
    addObstacle(this.grid, -(i + 1), cells);
    this.repredict(cells, EV_POINT, -1);
  }

  /** Put a checked point in the place of the point of its id. */
  protected replacePointEntry(point: Point): void {
    const old = this.pointAt.get(this.pointList, point.id) as Point;
    const i = this.pointAt.indexOf(this.pointList, point.id);
    const local = this.keepsLayout(0);
    this.pointAt.replace(this.pointList, point);
    if (!local) {
      this.markDirty();
      return;
    }
    removeObstacle(this.grid, -(i + 1), this.cellsOfObstacle(old.x, old.y, old.x, old.y));
    const cells = this.cellsOfObstacle(point.x, point.y, point.x, point.y);
    addObstacle(this.grid, -(i + 1), cells);
    this.repredict(cells, EV_POINT, i);
  }

  /** Remove the point `id` (which is in the list). */
  protected removePointEntry(id: string): void {
    const i = this.pointAt.indexOf(this.pointList, id);
    const old = this.pointList[i] as Point;
    const local = this.keepsLayout(-1);
    this.pointAt.remove(this.pointList, id);
    if (!local) {
      this.markDirty();
      return;
    }
    removeObstacle(this.grid, -(i + 1), this.cellsOfObstacle(old.x, old.y, old.x, old.y));
    this.pointAt.compact(this.pointList);
    renumberAfterRemoval(this.grid, undefined, i);
    this.repredict([], EV_POINT, i, true);
  }

  /**
   * Whether an edit about to change the number of segments and points by `change` can keep the
   * grid's layout and the predictions (GRID_OBSTACLE_RELAYOUT). Called before the lists change:
   * while the predictions are up to date, the lists hold no removed entry and the grid holds them.
   */
  private keepsLayout(change: number): boolean {
    if (this.dirty || this.fullObstacleRebuild) return false;
    const laidOut = this.gridObstacles;
    const after = this.lineList.length - this.globalLines.length + this.pointList.length + change;
    if (
      after <= GRID_OBSTACLE_RELAYOUT * Math.max(laidOut, GRID_MIN_BODIES) &&
      (laidOut <= GRID_MIN_BODIES || GRID_OBSTACLE_RELAYOUT * after >= laidOut)
    )
      return true;
    if (!this.layoutStillFits()) return false;
    this.gridObstacles = after;
    return true;
  }

  /**
   * Whether the layout a rebuild would choose now (broadPhase.ts's cost estimate, over the bodies
   * where they are and the obstacles before the edit) is of the current kind (sized by the bodies,
   * or by the obstacles) with level-0 cells within GRID_OBSTACLE_RELAYOUT of the current side. It
   * costs a pass over the bodies and the obstacles and the estimate, no prediction.
   */
  private layoutStillFits(): boolean {
    if (!this.opt.broadPhase) return true;
    const b = this.store;
    const radii: number[] = [];
    const box = [INF, INF, -INF, -INF];
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined) continue;
      radii.push(b.r[s] as number);
      const x = this.xAt(s, this.now);
      const y = this.yAt(s, this.now);
      box[0] = Math.min(box[0] as number, x);
      box[1] = Math.min(box[1] as number, y);
      box[2] = Math.max(box[2] as number, x);
      box[3] = Math.max(box[3] as number, y);
    }
    if (radii.length === 0) return true;
    const layout = this.chooseLayout(radii, box, 1);
    const w = layout[2];
    return (
      layout[6] === this.gridForObstacles &&
      w <= GRID_OBSTACLE_RELAYOUT * this.grid.w &&
      GRID_OBSTACLE_RELAYOUT * w >= this.grid.w
    );
  }

  /**
   * The edit is made in the lists and the grid: predict again the moving bodies whose scans cover
   * the level-0 cells `cells` (at their own level), and every body whose queued event is with
   * obstacle `index` of `kind` (EV_LINE or EV_POINT; -1: none). With `removed`, that obstacle
   * left its list: the events with the ones after it are renumbered.
   */
  private repredict(cells: readonly number[], kind: number, index: number, removed = false): void {
    this.changes++;
    const size = this.lineList.length + this.pointList.length;
    if (this.obstStamp.length < size) this.obstStamp = new Int32Array(2 * size);
    const b = this.store;
    const again = new Set<number>();
    const evKind = b.evKind;
    if (index >= 0)
      for (let s = 0; s < b.slotCount; s++) {
        if (evKind[s] !== kind || b.ids[s] === undefined) continue;
        const other = b.evOther[s] as number;
        if (other === index) again.add(s);
        else if (removed && other > index) b.evOther[s] = other - 1;
      }
    if (cells.length > 0) this.forEachBodyScanning(cells, (s) => again.add(s));
    // Out of the queue first: an entry whose event is with a removed obstacle cannot be ordered.
    for (const s of again) this.heap.remove(s);
    for (const s of again) this.predict(s);
  }

  /** Call `visit` for each moving body whose prediction scans the obstacles of a level-0 cell in `cells`. */
  private forEachBodyScanning(cells: readonly number[], visit: (s: number) => void): void {
    const g = this.grid;
    for (const j of g.occupied) {
      const nxj = g.nxOf[j] as number;
      const nyj = g.nyOf[j] as number;
      const base = g.base[j] as number;
      const near = new Set<number>();
      for (const c of cells) {
        const cx = (c % g.nx) >> j;
        const cy = ((c - (c % g.nx)) / g.nx) >> j;
        for (let y = Math.max(0, cy - 1); y <= Math.min(nyj - 1, cy + 1); y++)
          for (let x = Math.max(0, cx - 1); x <= Math.min(nxj - 1, cx + 1); x++) near.add(base + y * nxj + x);
      }
      for (const cell of near)
        for (let s = g.head[cell] as number; s >= 0; s = g.next[s] as number) if (this.isMoving(s)) visit(s);
    }
  }
}
