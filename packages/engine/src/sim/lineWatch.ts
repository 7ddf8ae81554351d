/**
 * The trap watch's crush in line (the proof: lineCrush.ts) in the World. At a collision of a
 * finite disc d with the moving immovable disc P (the trap watch has checked that no other
 * immovable body moves), when d and P keep to one axis-parallel line L, to the bit:
 *
 * - the end is the still body across L (a line, a point, an immovable disc at rest: footOf) whose
 *   surface is nearest beyond d, away from P;
 * - the row is every finite disc centred on L, keeping to it, between the end and P (d among them);
 * - every other finite disc ("aside") is farther from the row's stretch of L than its radius + the
 *   row's largest radius, and from P's path until t* than its radius + P's, each by more than it
 *   can travel before t* (a margin more; asideClear: a bound from the kinetic energy of the discs
 *   aside, which only the row or P could raise, without gravity; under gravity they must be at
 *   rest): none of them meets the row or P before t* (the earliest such contact would contradict
 *   these distances);
 * - the row's stretch of L keeps clear of every other line, point and immovable disc, and P's path
 *   meets none (pathClear): nothing else changes P's motion, or knocks a disc of the row off L.
 *
 * The report is a SimulationError at the event's time naming the row, P and the end, and what to do
 * (zenoAdvice.ts); its ids are the row (from P to the end), P, then the end. It is thrown before
 * anything is counted or changed, so the same event throws again.
 */
import { ZENO_TRAP_SCALE, ZENO_TRAP_SLACK } from "../tolerances.js";
import { CellCrossings } from "./cellCrossings.js";
import { SimulationError } from "./errors.js";
import { footOf, type LineDisc, lineAxis, lineCloses, onLine, orderedSum } from "./lineCrush.js";
import { length, triangleCoreDistance } from "./pocketGeometry.js";
import { quoteId } from "./refusalText.js";
import { before, fill, named, type Side, scratch } from "./trapSides.js";
import { bodiesNamed, crushAdvice } from "./zenoAdvice.js";

const INF = Number.POSITIVE_INFINITY;

/** The triangle holding P's path until t*, filled by the proofs (x0, y0, x1, y1, x2, y2). */
export const hull: Float64Array = new Float64Array(6);
/** The stretch of line the row keeps to, and it as a flat triangle. */
const corridor = new Float64Array(4);
const strip = new Float64Array(6);

export class LineWatch extends CellCrossings {
  /**
   * Throw a SimulationError if slot d, a finite disc about to collide with the moving immovable
   * slot p, is proven crushed in line as above. Changes nothing.
   */
  protected guardLineCrush(d: number, p: number): void {
    const b = this.store;
    const m = b.mot;
    const t = this.now;
    const disc = this.lineDisc(d);
    const k = lineAxis(disc, m, p * 8);
    if (k < 0) return;
    const across = k === 0 ? disc.y : disc.x;
    const along = k === 0 ? disc.x : disc.y;
    const side = Math.sign((k === 0 ? this.xAt(p, t) : this.yAt(p, t)) - along);
    // Every other finite disc: on L (in the row or not) or aside.
    const others: LineDisc[] = [];
    const otherSlots: number[] = [];
    const aside: number[] = [];
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined || s === d || s === p) continue;
      if (b.m[s] === INF) {
        if (this.isMoving(s)) return;
        continue;
      }
      const o = this.lineDisc(s);
      if (onLine(o, k, across)) {
        others.push(o);
        otherSlots.push(s);
      } else aside.push(s);
    }
    const end = this.nearestEnd(k, across, along, side, disc.r, p);
    if (end === null) return;
    const R = b.r[p] as number;
    const inRow: boolean[] = [];
    const tStar = lineCloses(t, disc, m, p * 8, R, end.core, hull, corridor, others, inRow);
    if (Number.isNaN(tStar)) return;
    const row = [d];
    let rMin = disc.r;
    let rMax = disc.r;
    for (let i = 0; i < others.length; i++) {
      const s = otherSlots[i] as number;
      if (inRow[i] === true) {
        row.push(s);
        rMin = Math.min(rMin, b.r[s] as number);
        rMax = Math.max(rMax, b.r[s] as number);
      } else aside.push(s);
    }
    const margin = ZENO_TRAP_SLACK * rMin;
    if (!this.pathClear(p, R, margin)) return;
    strip[0] = corridor[0] as number;
    strip[1] = corridor[1] as number;
    strip[2] = corridor[2] as number;
    strip[3] = corridor[3] as number;
    strip[4] = corridor[2] as number;
    strip[5] = corridor[3] as number;
    if (!this.stripClear(p, end, rMax + margin)) return;
    if (!this.asideClear(aside, tStar - t, rMin, rMax, R)) return;
    // The row named from P to the end.
    const at = (s: number): number => side * (k === 0 ? this.xAt(s, t) : this.yAt(s, t));
    row.sort((u, v) => at(v) - at(u));
    const ids = row.map((s) => b.ids[s] as string);
    const crusher = b.ids[p] as string;
    throw new SimulationError(
      `${bodiesNamed(ids)} ${ids.length === 1 ? "is" : "are"} crushed in line between the immovable body ${quoteId(crusher)} and ${named(end)}, which close on ${ids.length === 1 ? "it" : "them"} by t=${tStar}: infinitely many collisions before then (a Zeno state: a disc crushed by an immovable body), which the exact model cannot pass: ${crushAdvice([crusher], [named(end)], tStar)}`,
      t,
      [...ids, crusher, end.id],
    );
  }

  /**
   * Whether none of the finite discs `aside` (slots off the row) can reach the row's stretch of L
   * (in `strip`, the row's largest radius rMax) or P's path (in `hull`, P's radius R) within `span`
   * from now. Without gravity their accelerations are friction's, which takes energy away, and their
   * collisions with one another and with still bodies keep it: until one of them first meets the row
   * or P, their kinetic energy E never grows, so none moves faster than sqrt(2 E / m) (m its mass),
   * nor farther than that times `span`. Under gravity they must be at rest (E = 0): a disc at rest
   * with no acceleration stays so until struck. Each test keeps the proof's margin,
   * ZENO_TRAP_SLACK × rMin, or that slack of the disc's magnitudes / ZENO_TRAP_SCALE when larger
   * (a huge disc aside), so that round-off cannot turn it.
   */
  private asideClear(aside: readonly number[], span: number, rMin: number, rMax: number, R: number): boolean {
    const b = this.store;
    const t = this.now;
    const gravity = this.gx !== 0 || this.gy !== 0;
    const energies: number[] = [];
    for (const s of aside) {
      if (gravity && this.isMoving(s)) return false;
      const vx = this.vxAt(s, t);
      const vy = this.vyAt(s, t);
      energies.push(0.5 * (b.m[s] as number) * (vx * vx + vy * vy));
    }
    const energy = orderedSum(energies);
    for (const s of aside) {
      const x = this.xAt(s, t);
      const y = this.yAt(s, t);
      const rad = b.r[s] as number;
      const reach = span * Math.sqrt((2 * energy) / (b.m[s] as number));
      const size = Math.max(
        Math.abs(x),
        Math.abs(y),
        rad,
        reach,
        Math.abs(t) * length(this.vxAt(s, t), this.vyAt(s, t)),
      );
      const margin = ZENO_TRAP_SLACK * Math.max(rMin, size / ZENO_TRAP_SCALE);
      if (!(triangleCoreDistance(strip, fill("point", x, y, x, y, 0)) > rad + rMax + reach + margin))
        return false;
      if (!(triangleCoreDistance(hull, fill("point", x, y, x, y, 0)) > rad + R + reach + margin))
        return false;
    }
    return true;
  }

  /** Slot s's motion now, as the proof of a crush in line reads it. */
  private lineDisc(s: number): LineDisc {
    const b = this.store;
    const t = this.now;
    return {
      x: this.xAt(s, t),
      y: this.yAt(s, t),
      vx: this.vxAt(s, t),
      vy: this.vyAt(s, t),
      ax: b.mot[s * 8 + 5] as number,
      ay: b.mot[s * 8 + 6] as number,
      r: b.r[s] as number,
    };
  }

  /**
   * The still body across L (axis k, at `across`) whose surface is nearest beyond `along` on the
   * side away from P (P on the `side` of it), in the canonical order of sides; null when none.
   */
  private nearestEnd(
    k: number,
    across: number,
    along: number,
    side: number,
    r: number,
    p: number,
  ): Side | null {
    const b = this.store;
    let best: Side | null = null;
    const consider = (rank: number, id: string): void => {
      const foot = footOf(scratch, k, across);
      if (Number.isNaN(foot) || Math.sign(along - foot) !== side) return;
      const gap = side * (along - foot) - scratch.rad - r;
      if (best === null || before(gap, rank, id, best)) best = { core: { ...scratch }, gap, rank, id };
    };
    for (const l of this.lineList) {
      fill(l.kind, l.x1, l.y1, l.x2, l.y2, 0);
      consider(0, l.id);
    }
    for (const q of this.pointList) {
      fill("point", q.x, q.y, q.x, q.y, 0);
      consider(1, q.id);
    }
    for (let s = 0; s < b.slotCount; s++) {
      const id = b.ids[s];
      if (id === undefined || s === p || b.m[s] !== INF) continue;
      const x = b.mot[s * 8 + 1] as number;
      const y = b.mot[s * 8 + 2] as number;
      fill("point", x, y, x, y, b.r[s] as number);
      consider(2, id);
    }
    return best;
  }

  /**
   * Whether the stretch of line in `strip` keeps more than `reach` (plus their own radius) from
   * every line, point and immovable disc but slot p and the side `end`: the row on it touches
   * nothing else.
   */
  private stripClear(p: number, end: Side, reach: number): boolean {
    const b = this.store;
    for (const l of this.lineList)
      if (!(end.rank === 0 && end.id === l.id))
        if (!(triangleCoreDistance(strip, fill(l.kind, l.x1, l.y1, l.x2, l.y2, 0)) > reach)) return false;
    for (const q of this.pointList)
      if (!(end.rank === 1 && end.id === q.id))
        if (!(triangleCoreDistance(strip, fill("point", q.x, q.y, q.x, q.y, 0)) > reach)) return false;
    for (let s = 0; s < b.slotCount; s++) {
      const id = b.ids[s];
      if (id === undefined || s === p || b.m[s] !== INF || (end.rank === 2 && end.id === id)) continue;
      const qx = b.mot[s * 8 + 1] as number;
      const qy = b.mot[s * 8 + 2] as number;
      const rad = b.r[s] as number;
      if (!(triangleCoreDistance(strip, fill("point", qx, qy, qx, qy, rad)) > reach + rad)) return false;
    }
    return true;
  }

  /**
   * Whether slot p's path (radius R) over the triangle in `hull` stays more than `margin` clear of
   * every line, point and immovable disc (where it is now; the trap watch answers for those that
   * move): it meets nothing that would change its motion.
   */
  protected pathClear(p: number, R: number, margin: number): boolean {
    const b = this.store;
    for (const l of this.lineList)
      if (!(triangleCoreDistance(hull, fill(l.kind, l.x1, l.y1, l.x2, l.y2, 0)) > R + margin)) return false;
    for (const q of this.pointList)
      if (!(triangleCoreDistance(hull, fill("point", q.x, q.y, q.x, q.y, 0)) > R + margin)) return false;
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined || s === p || b.m[s] !== INF) continue;
      // Where it is now (one at rest: where it was put, to the bit).
      const qx = this.xAt(s, this.now);
      const qy = this.yAt(s, this.now);
      const rad = b.r[s] as number;
      if (!(triangleCoreDistance(hull, fill("point", qx, qy, qx, qy, rad)) > R + rad + margin)) return false;
    }
    return true;
  }
}
