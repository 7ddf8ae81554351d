/**
 * Prediction: what each body runs into next. Each body holds its earliest predicted interaction
 * (collision or stop) and its next cell crossing; the heap key is the earlier of the two. Every pair
 * prediction is a pure function of the two motions (solved from the later of their start times),
 * so it gives the same bits whenever and from whichever side it is computed.
 */
import { positionAt, velocityAt } from "../physics/motion.js";
import { discDiscTime, discLineCrossings } from "../physics/timeOfImpact.js";
import { EV_BODY, EV_LINE, EV_NONE, EV_POINT, EV_STOP } from "./bodyStore.js";
import { axisExit } from "./cellExit.js";
import { BIG_CELL } from "./grid.js";
import { type Line, lineParameter, type Point, parameterOnLine } from "./obstacles.js";
import { SimState } from "./state.js";

const INF = Number.POSITIVE_INFINITY;
const sides = new Float64Array(2);
const side = new Float64Array(1);

function idLess(a: string, b: string): boolean {
  return a < b;
}
export class Predictor extends SimState {
  /** Recompute every body's predictions (after a rebuild or a change of obstacles or globals). */
  protected predictAll(): void {
    const b = this.store;
    for (let s = 0; s < b.slotCount; s++) if (b.ids[s] !== undefined) this.predict(s);
    this.dirty = false;
  }

  // ---- prediction ---------------------------------------------------------------------------

  /**
   * Earliest contact time of bodies s and o, or +Infinity. The result is symmetric (it depends
   * only on the two motions), so the last pair solved is remembered: after a collision both
   * participants are re-predicted and the second would solve the same pair again.
   */
  protected pairTime(s: number, o: number): number {
    const b = this.store;
    const vs = b.version[s] as number;
    const vo = b.version[o] as number;
    if (
      o === this.memoS &&
      s === this.memoO &&
      vo === this.memoVS &&
      vs === this.memoVO &&
      this.now === this.memoTime
    )
      return this.memoResult;
    const t = this.solvePair(s, o);
    this.memoS = s;
    this.memoO = o;
    this.memoVS = vs;
    this.memoVO = vo;
    this.memoTime = this.now;
    this.memoResult = t;
    return t;
  }

  private memoS = -1;
  private memoO = -1;
  private memoVS = -1;
  private memoVO = -1;
  private memoTime = Number.NaN;
  private memoResult = INF;

  private solvePair(s: number, o: number): number {
    const b = this.store;
    const ts = b.mot[s * 8 + 0] as number;
    const to = b.mot[o * 8 + 0] as number;
    const ends = b.mot[s * 8 + 7] as number;
    const endo = b.mot[o * 8 + 7] as number;
    // Path boxes are finite only for motions that end (friction) or rest: when s's box is
    // unbounded the boxes cannot be disjoint, and the partner's box is not even loaded.
    if (this.opt.pathBounds && (b.boxMaxX[s] as number) < INF) {
      if (
        (b.boxMinX[s] as number) > (b.boxMaxX[o] as number) ||
        (b.boxMinX[o] as number) > (b.boxMaxX[s] as number) ||
        (b.boxMinY[s] as number) > (b.boxMaxY[o] as number) ||
        (b.boxMinY[o] as number) > (b.boxMaxY[s] as number)
      )
        return INF;
    }
    const tb = Math.max(ts, to);
    const hi = Math.min(ends, endo) - tb;
    const axs = b.mot[s * 8 + 5] as number;
    const ays = b.mot[s * 8 + 6] as number;
    const axo = b.mot[o * 8 + 5] as number;
    const ayo = b.mot[o * 8 + 6] as number;
    const dx =
      positionAt(to, b.mot[o * 8 + 1] as number, b.mot[o * 8 + 3] as number, axo, tb) -
      positionAt(ts, b.mot[s * 8 + 1] as number, b.mot[s * 8 + 3] as number, axs, tb);
    const dy =
      positionAt(to, b.mot[o * 8 + 2] as number, b.mot[o * 8 + 4] as number, ayo, tb) -
      positionAt(ts, b.mot[s * 8 + 2] as number, b.mot[s * 8 + 4] as number, ays, tb);
    const ux =
      velocityAt(to, b.mot[o * 8 + 3] as number, axo, tb) -
      velocityAt(ts, b.mot[s * 8 + 3] as number, axs, tb);
    const uy =
      velocityAt(to, b.mot[o * 8 + 4] as number, ayo, tb) -
      velocityAt(ts, b.mot[s * 8 + 4] as number, ays, tb);
    // Cheap rejection before any solve: with no relative acceleration a receding pair never meets.
    if (axo === axs && ayo === ays && dx * ux + dy * uy >= 0 && this.opt.quadraticFastPath) return INF;
    const R = (b.r[s] as number) + (b.r[o] as number);
    const tau = discDiscTime(
      dx,
      dy,
      ux,
      uy,
      axo - axs,
      ayo - ays,
      R,
      this.now - tb,
      hi,
      this.opt.quadraticFastPath,
    );
    if (tau === INF) return INF;
    const t = tb + tau;
    return Math.max(t, this.now);
  }

  /** Earliest contact of body s with a point at (px, py), or +Infinity. */
  protected pointTime(s: number, px: number, py: number): number {
    const b = this.store;
    const t0 = b.mot[s * 8 + 0] as number;
    const tau = discDiscTime(
      (b.mot[s * 8 + 1] as number) - px,
      (b.mot[s * 8 + 2] as number) - py,
      b.mot[s * 8 + 3] as number,
      b.mot[s * 8 + 4] as number,
      b.mot[s * 8 + 5] as number,
      b.mot[s * 8 + 6] as number,
      b.r[s] as number,
      this.now - t0,
      (b.mot[s * 8 + 7] as number) - t0,
      this.opt.quadraticFastPath,
    );
    if (tau === INF) return INF;
    const t = t0 + tau;
    return Math.max(t, this.now);
  }

  /**
   * Earliest contact of body s with the line (its interior for rays and segments; their end points
   * are tested as points). Returns the time, or +Infinity.
   */
  protected lineTime(s: number, line: Line): number {
    const b = this.store;
    const t0 = b.mot[s * 8 + 0] as number;
    const lo = this.now - t0;
    const hi = (b.mot[s * 8 + 7] as number) - t0;
    const x0 = b.mot[s * 8 + 1] as number;
    const y0 = b.mot[s * 8 + 2] as number;
    const vx = b.mot[s * 8 + 3] as number;
    const vy = b.mot[s * 8 + 4] as number;
    const ax = b.mot[s * 8 + 5] as number;
    const ay = b.mot[s * 8 + 6] as number;
    discLineCrossings(
      x0,
      y0,
      vx,
      vy,
      ax,
      ay,
      line.x1,
      line.y1,
      line.nx,
      line.ny,
      b.r[s] as number,
      lo,
      hi,
      sides,
    );
    let best = INF;
    for (let k = 0; k < 2; k++) {
      const tau = sides[k] as number;
      if (tau >= best) continue;
      if (line.kind !== "line") {
        // Where the disc is at the contact: a contact under way is now (its crossing of the
        // infinite line may lie long before, beyond the end of a ray or segment).
        const tc = Math.max(tau, lo);
        const lambda = lineParameter(line, x0 + tc * (vx + 0.5 * ax * tc), y0 + tc * (vy + 0.5 * ay * tc));
        if (!parameterOnLine(line.kind, lambda)) continue;
      }
      best = tau;
    }
    if (best === INF) return INF;
    const t = t0 + best;
    return Math.max(t, this.now);
  }

  /** Whether candidate (kind k1, other o1) comes before (k2, o2) for body s at the same time. */
  protected candidateLess(k1: number, o1: number, a1: number, k2: number, o2: number, a2: number): boolean {
    if (k1 !== k2) return k1 < k2;
    if (k1 === EV_BODY) return idLess(this.store.ids[o1] as string, this.store.ids[o2] as string);
    if (k1 === EV_LINE) {
      const i1 = (this.lineList[o1] as Line).id;
      const i2 = (this.lineList[o2] as Line).id;
      return i1 !== i2 ? idLess(i1, i2) : a1 < a2;
    }
    if (k1 === EV_POINT) return idLess((this.pointList[o1] as Point).id, (this.pointList[o2] as Point).id);
    return false;
  }

  /** Offer a candidate event to body s; it is kept if earlier (or canonically first at the same time). */
  protected offer(s: number, t: number, kind: number, other: number, aux: number): void {
    const b = this.store;
    const cur = b.evTime[s] as number;
    if (t > cur) return;
    if (
      t === cur &&
      !this.candidateLess(
        kind,
        other,
        aux,
        b.evKind[s] as number,
        b.evOther[s] as number,
        b.evAux[s] as number,
      )
    )
      return;
    b.evTime[s] = t;
    b.evKind[s] = kind;
    b.evOther[s] = other;
    b.evAux[s] = aux;
    b.evOtherVersion[s] = kind === EV_BODY ? (b.version[other] as number) : 0;
  }

  /** Test body s against the bodies in one grid cell. */
  protected scanCell(s: number, cell: number, moving: boolean): void {
    const grid = this.grid;
    for (let o = grid.head[cell] as number; o >= 0; o = grid.next[o] as number) {
      if (o === s) continue;
      if (!moving && this.opt.restingSkip && !this.isMoving(o)) continue;
      const t = this.pairTime(s, o);
      if (t !== INF) this.offer(s, t, EV_BODY, o, 0);
    }
  }

  /** Recompute everything body s can run into next, and its next cell crossing. */
  protected predict(s: number): void {
    const b = this.store;
    const moving = this.isMoving(s);
    b.evTime[s] = INF;
    b.evKind[s] = EV_NONE;
    const tEnd = b.mot[s * 8 + 7] as number;
    if (tEnd < INF) this.offer(s, Math.max(tEnd, this.now), EV_STOP, -1, 0);
    const grid = this.grid;
    const cell = grid.cellOf[s] as number;
    if (cell === BIG_CELL) {
      this.predictBig(s, moving);
      return;
    }
    const cx = cell % grid.nx;
    const cy = (cell - cx) / grid.nx;
    this.stamp++;
    for (let y = cy - 1; y <= cy + 1; y++) {
      if (y < 0 || y >= grid.ny) continue;
      for (let x = cx - 1; x <= cx + 1; x++) {
        if (x < 0 || x >= grid.nx) continue;
        this.scanCell(s, y * grid.nx + x, moving);
        if (moving) this.scanCellObstacles(s, y * grid.nx + x);
      }
    }
    if (moving) for (const i of this.globalLines) this.testLine(s, i);
    for (const o of this.bigBodies) this.testBody(s, o, moving);
    b.crossTime[s] = moving && (grid.nx > 1 || grid.ny > 1) ? this.crossing(s, cx, cy) : INF;
    const key = Math.min(b.evTime[s] as number, b.crossTime[s] as number);
    this.heap.set(s, key);
  }

  /** Test body s (moving or not) against body o. */
  protected testBody(s: number, o: number, moving: boolean): void {
    if (o === s || (!moving && this.opt.restingSkip && !this.isMoving(o))) return;
    const t = this.pairTime(s, o);
    if (t !== INF) this.offer(s, t, EV_BODY, o, 0);
  }

  /** Predict a big body (state.ts): against every body and obstacle; it never crosses cells. */
  private predictBig(s: number, moving: boolean): void {
    const b = this.store;
    for (let o = 0; o < b.slotCount; o++) if (b.ids[o] !== undefined) this.testBody(s, o, moving);
    if (moving) {
      for (let i = 0; i < this.lineList.length; i++) this.testLine(s, i);
      for (let i = 0; i < this.pointList.length; i++) {
        const p = this.pointList[i] as Point;
        const t = this.pointTime(s, p.x, p.y);
        if (t !== INF) this.offer(s, t, EV_POINT, i, 0);
      }
    }
    b.crossTime[s] = INF;
    this.heap.set(s, b.evTime[s] as number);
  }

  /** Test body s against line i: its interior, and the end points of rays and segments. */
  protected testLine(s: number, i: number): void {
    const line = this.lineList[i] as Line;
    const t = this.lineTime(s, line);
    if (t !== INF) this.offer(s, t, EV_LINE, i, 0);
    if (line.kind !== "line") {
      const t1 = this.pointTime(s, line.x1, line.y1);
      if (t1 !== INF) this.offer(s, t1, EV_LINE, i, 1);
      if (line.kind === "segment") {
        const t2 = this.pointTime(s, line.x2, line.y2);
        if (t2 !== INF) this.offer(s, t2, EV_LINE, i, 2);
      }
    }
  }

  /** Test body s against the segments and points registered in one cell (each once per stamp). */
  protected scanCellObstacles(s: number, cell: number): void {
    const grid = this.grid;
    const end = grid.obstStart[cell + 1] as number;
    for (let k = grid.obstStart[cell] as number; k < end; k++) {
      const code = grid.obstList[k] as number;
      const key = code >= 0 ? code : this.lineList.length - code - 1;
      if (this.obstStamp[key] === this.stamp) continue;
      this.obstStamp[key] = this.stamp;
      if (code >= 0) this.testLine(s, code);
      else {
        const p = this.pointList[-code - 1] as Point;
        const t = this.pointTime(s, p.x, p.y);
        if (t !== INF) this.offer(s, t, EV_POINT, -code - 1, 0);
      }
    }
  }

  /** Time at which body s (in cell cx, cy) next leaves its cell; direction stored in crossDir. */
  protected crossing(s: number, cx: number, cy: number): number {
    const b = this.store;
    const grid = this.grid;
    const t0 = b.mot[s * 8 + 0] as number;
    const lo = this.now - t0;
    const hi = (b.mot[s * 8 + 7] as number) - t0;
    // Cell bounds without allocation; edge cells extend to infinity.
    const x0 = cx === 0 ? -INF : grid.boundaryX(cx);
    const x1 = cx === grid.nx - 1 ? INF : grid.boundaryX(cx + 1);
    const y0 = cy === 0 ? -INF : grid.boundaryY(cy);
    const y1 = cy === grid.ny - 1 ? INF : grid.boundaryY(cy + 1);
    const tx = axisExit(
      b.mot[s * 8 + 1] as number,
      b.mot[s * 8 + 3] as number,
      0.5 * (b.mot[s * 8 + 5] as number),
      lo,
      hi,
      x0,
      x1,
      side,
    );
    const sx = side[0] as number;
    const ty = axisExit(
      b.mot[s * 8 + 2] as number,
      b.mot[s * 8 + 4] as number,
      0.5 * (b.mot[s * 8 + 6] as number),
      lo,
      hi,
      y0,
      y1,
      side,
    );
    const sy = side[0] as number;
    // Directions: 0 -x, 1 +x, 2 -y, 3 +y.
    const best = Math.min(tx, ty);
    b.crossDir[s] = best === INF ? -1 : tx <= ty ? (sx < 0 ? 0 : 1) : sy < 0 ? 2 : 3;
    return best === INF ? INF : Math.max(this.now, t0 + best);
  }
}
