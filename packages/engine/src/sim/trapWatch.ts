/**
 * The trap watch: reports a disc crushed by a moving immovable disc in a pocket of two or three
 * still obstacles (a corner of two lines, a wall and a floor, two immovable discs at rest, a dead
 * end...) after a few thousand events, by a geometric proof (pocket.ts) instead of the convergence
 * of event times, which takes the Zeno watch millions of events there.
 *
 * At a collision between a finite disc d and a moving immovable disc P (tried at some of them only:
 * ZENO_TRAP_EVERY, ZENO_TRAP_TRIES): the ZENO_TRAP_CANDIDATES obstacles and immovable discs at
 * rest nearest d, in a canonical order (distance, then kind and id, so that the verdict does not
 * depend on the order they were added in), are tried in chains of two and three as the pocket's
 * still sides. A chain is reported when the pocket is proven to close on d at t* and P's path until
 * t* meets no obstacle and no immovable disc: nothing else can change P's motion (finite discs do
 * not); and no other immovable disc can reach P's path or a side of the pocket before t*
 * (moversClear: without gravity, by a bound on their speeds; under gravity none may move). The
 * report is a SimulationError at the event's time naming the disc, the crusher and the sides, and
 * what to do (zenoAdvice.ts); its ids are the disc, the crusher, the immovable discs among the sides,
 * then the lines and points among them, in the order the message names them. It is thrown before
 * anything is counted or changed, so the same event throws again. When no pocket is proven,
 * a crush in line is tried (lineWatch.ts: d and P on one axis-parallel line, pressing the row of
 * discs on it against a still end).
 */
import { ZENO_TRAP_CANDIDATES, ZENO_TRAP_SLACK } from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { orderedSum } from "./lineCrush.js";
import { hull, LineWatch } from "./lineWatch.js";
import { pocketCloses } from "./pocket.js";
import { coreDistance, length, triangleCoreDistance } from "./pocketGeometry.js";
import { quoteId } from "./refusalText.js";
import { before, fill, named, type Side, scratch } from "./trapSides.js";
import { crushAdvice } from "./zenoAdvice.js";

const INF = Number.POSITIVE_INFINITY;

/**
 * Insert the side in `scratch` (its gap, rank and id given) into `kept` (sorted, at most
 * ZENO_TRAP_CANDIDATES long) if it is among the first, as a copy.
 */
function keep(kept: Side[], gap: number, rank: number, id: string): void {
  if (kept.length === ZENO_TRAP_CANDIDATES && !before(gap, rank, id, kept[kept.length - 1] as Side)) return;
  let i = kept.length;
  while (i > 0 && before(gap, rank, id, kept[i - 1] as Side)) i--;
  kept.splice(i, 0, { core: { ...scratch }, gap, rank, id });
  if (kept.length > ZENO_TRAP_CANDIDATES) kept.pop();
}

export class TrapWatch extends LineWatch {
  /**
   * Throw a SimulationError if the collision of slot s with slot o (about to be processed now) is
   * that of a finite disc with the moving immovable disc that is proven to crush it. Changes
   * nothing. The guard calls it at some collisions only (ZENO_TRAP_EVERY, ZENO_TRAP_TRIES).
   */
  protected guardTrap(s: number, o: number): void {
    const b = this.store;
    const sInf = b.m[s] === INF;
    if (sInf === (b.m[o] === INF)) return;
    const p = sInf ? s : o;
    const d = sInf ? o : s;
    if (!this.isMoving(p)) return;
    const sides = this.sidesNear(d, p);
    const t = this.now;
    const cx = this.xAt(d, t);
    const cy = this.yAt(d, t);
    const r = b.r[d] as number;
    const R = b.r[p] as number;
    const moreSize = Math.abs(t) * length(this.vxAt(d, t), this.vyAt(d, t));
    // Chains of two sides (each pair), then of three (each side between each pair of the others).
    const chains: Side[][] = [];
    for (let i = 0; i < sides.length; i++)
      for (let j = i + 1; j < sides.length; j++) chains.push([sides[i] as Side, sides[j] as Side]);
    for (let k = 0; k < sides.length; k++)
      for (let i = 0; i < sides.length; i++)
        for (let j = i + 1; j < sides.length; j++)
          if (i !== k && j !== k) chains.push([sides[i] as Side, sides[k] as Side, sides[j] as Side]);
    for (const chain of chains) {
      const cores = chain.map((side) => side.core);
      const tStar = pocketCloses(t, cx, cy, r, b.mot, p * 8, R, cores, hull, moreSize);
      if (Number.isNaN(tStar) || !this.pathClear(p, R, ZENO_TRAP_SLACK * r)) continue;
      if (!this.moversClear(p, chain, tStar - t, ZENO_TRAP_SLACK * r)) continue;
      const names = chain.map(named);
      const crusher = b.ids[p] as string;
      const ids = [b.ids[d] as string, crusher];
      for (const side of chain) if (side.rank === 2) ids.push(side.id);
      for (const side of chain) if (side.rank !== 2) ids.push(side.id);
      throw new SimulationError(
        `body ${quoteId(b.ids[d] as string)} is shut in by the immovable body ${quoteId(crusher)}, ${names.slice(0, -1).join(", ")} and ${names[names.length - 1] as string}, which close on it by t=${tStar}: infinitely many collisions before then (a Zeno state: a disc crushed by an immovable body), which the exact model cannot pass: ${crushAdvice([crusher], names, tStar)}`,
        t,
        ids,
      );
    }
    this.guardLineCrush(d, p);
  }

  /** The immovable discs other than p that move, as the last sidesNear found them. */
  private readonly movers: number[] = [];

  /**
   * The obstacles and immovable discs at rest (other than p) nearest slot d, in canonical order, at
   * most ZENO_TRAP_CANDIDATES of them. Sets `movers`.
   */
  private sidesNear(d: number, p: number): Side[] {
    const b = this.store;
    const t = this.now;
    const x = this.xAt(d, t);
    const y = this.yAt(d, t);
    const r = b.r[d] as number;
    const kept: Side[] = [];
    this.movers.length = 0;
    for (const l of this.lineList) {
      const gap = coreDistance(fill(l.kind, l.x1, l.y1, l.x2, l.y2, 0), x, y) - r;
      keep(kept, gap, 0, l.id);
    }
    for (const q of this.pointList)
      keep(kept, coreDistance(fill("point", q.x, q.y, q.x, q.y, 0), x, y) - r, 1, q.id);
    for (let s = 0; s < b.slotCount; s++) {
      const id = b.ids[s];
      if (id === undefined || s === p || s === d) continue;
      if (b.m[s] !== INF) continue;
      if (this.isMoving(s)) {
        this.movers.push(s);
        continue;
      }
      const qx = b.mot[s * 8 + 1] as number;
      const qy = b.mot[s * 8 + 2] as number;
      const rad = b.r[s] as number;
      keep(kept, coreDistance(fill("point", qx, qy, qx, qy, rad), x, y) - rad - r, 2, id);
    }
    return kept;
  }

  /**
   * Whether no immovable disc but p can touch P's path until t* (in `hull`, `span` from now) or
   * an immovable disc among the `chain`'s sides (at rest) before then: the one thing that could
   * change their motions, for two immovable discs exchange the components of their velocities
   * along the normal. Without gravity the immovable discs' sum of squared speeds never grows
   * (exchanges keep it, obstacles reflect, friction slows), until one of them touches P or a side:
   * none moves faster than its square root V, so each (moving or not: one at rest may be struck)
   * keeps within V × span of where it is, and the test is made that much farther (and `margin`
   * more). Under gravity, no other immovable disc may move.
   */
  private moversClear(p: number, chain: readonly Side[], span: number, margin: number): boolean {
    if (this.movers.length === 0) return true;
    if (this.gx !== 0 || this.gy !== 0) return false;
    const b = this.store;
    const t = this.now;
    const squares: number[] = [];
    for (const q of this.movers) {
      const vx = this.vxAt(q, t);
      const vy = this.vyAt(q, t);
      squares.push(vx * vx + vy * vy);
    }
    const reach = span * Math.sqrt(orderedSum(squares));
    const R = b.r[p] as number;
    for (let s = 0; s < b.slotCount; s++) {
      const id = b.ids[s];
      if (id === undefined || s === p || b.m[s] !== INF) continue;
      if (chain.some((side) => side.rank === 2 && side.id === id)) continue;
      const x = this.xAt(s, t);
      const y = this.yAt(s, t);
      const rad = b.r[s] as number;
      if (!(triangleCoreDistance(hull, fill("point", x, y, x, y, 0)) > R + rad + reach + margin))
        return false;
      for (const side of chain) {
        if (side.rank !== 2) continue;
        const apart = length(x - side.core.x1, y - side.core.y1);
        if (!(apart > rad + side.core.rad + reach + margin)) return false;
      }
    }
    return true;
  }
}
