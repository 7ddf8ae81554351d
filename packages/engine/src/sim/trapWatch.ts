/**
 * The trap watch: reports a disc crushed by a moving immovable disc in a pocket of two or three
 * still obstacles (a corner of two lines, a wall and a floor, two immovable discs at rest, a dead
 * end...) after a few thousand events, by a geometric proof (pocket.ts) instead of the convergence
 * of event times, which takes the Zeno watch millions of events there.
 *
 * At a collision between a finite disc d and a moving immovable disc P (tried at some of them only:
 * ZENO_TRAP_EVERY, ZENO_TRAP_TRIES), when P is the only immovable body that moves: the
 * ZENO_TRAP_CANDIDATES obstacles and immovable discs nearest d, in a canonical order (distance, then
 * kind and id, so that the verdict does not depend on the order they were added in), are tried in
 * chains of two and three as the pocket's still sides. A chain is reported when the pocket is
 * proven to close on d at t* and P's path until t* meets no obstacle and no immovable disc: nothing
 * else can change P's motion (finite discs do not, and no other immovable body moves). The report
 * is a SimulationError at the event's time with ids [] (a Zeno state of many events), thrown
 * before anything is counted or changed, so the same event throws again. When no pocket is proven
 * and d is the only finite disc in the World, each of those sides is tried as the end of a crush
 * in line (lineCrush.ts), the stretch of line d keeps to clear of every other obstacle.
 */
import { ZENO_TRAP_CANDIDATES, ZENO_TRAP_SLACK } from "../tolerances.js";
import { CellCrossings } from "./cellCrossings.js";
import { SimulationError } from "./errors.js";
import { lineCloses } from "./lineCrush.js";
import { pocketCloses } from "./pocket.js";
import { type Core, type CoreKind, coreDistance, length, triangleCoreDistance } from "./pocketGeometry.js";
import { quoteId } from "./refusalText.js";

const INF = Number.POSITIVE_INFINITY;

/** A side the pocket may have: its core and its order key (which also names it). */
interface Side {
  core: Core;
  /** Distance from d's surface to it. */
  gap: number;
  /** 0 line, 1 point, 2 body (ids are unique per kind). */
  rank: number;
  id: string;
}

const hull = new Float64Array(6);
/** The stretch of line a disc crushed in line keeps to, and it as a flat triangle. */
const corridor = new Float64Array(4);
const strip = new Float64Array(6);

/** How the message names a side. */
function named(side: Side): string {
  return `${side.rank === 0 ? "line" : side.rank === 1 ? "point" : "the immovable body"} ${quoteId(side.id)}`;
}

/** Canonical order of sides: nearer first, then lines, points, bodies, then by id. */
function before(gap: number, rank: number, id: string, v: Side): boolean {
  if (gap !== v.gap) return gap < v.gap;
  if (rank !== v.rank) return rank < v.rank;
  return id < v.id;
}

/** A core to fill in place: the scans measure every obstacle without allocating one each. */
const scratch: { -readonly [K in keyof Core]: Core[K] } = {
  kind: "point",
  x1: 0,
  y1: 0,
  x2: 0,
  y2: 0,
  rad: 0,
};

/** The scratch core, filled with a core of this shape. */
function fill(kind: CoreKind, x1: number, y1: number, x2: number, y2: number, rad: number): Core {
  scratch.kind = kind;
  scratch.x1 = x1;
  scratch.y1 = y1;
  scratch.x2 = x2;
  scratch.y2 = y2;
  scratch.rad = rad;
  return scratch;
}

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

export class TrapWatch extends CellCrossings {
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
    if (sides === null) return;
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
      const names = chain.map(named);
      throw new SimulationError(
        `body ${quoteId(b.ids[d] as string)} is shut in by the immovable body ${quoteId(b.ids[p] as string)}, ${names.slice(0, -1).join(", ")} and ${names[names.length - 1] as string}, which close on it by t=${tStar}: infinitely many collisions before then (a Zeno state: a disc crushed by an immovable body), which the exact model cannot pass`,
        t,
      );
    }
    if (this.alone) this.guardLineCrush(d, p, sides);
  }

  /**
   * The crush in line (lineCrush.ts), for slot d, the only finite disc, and the moving immovable
   * slot p: each of the nearest `sides` is tried as the end.
   */
  private guardLineCrush(d: number, p: number, sides: readonly Side[]): void {
    const b = this.store;
    const m = b.mot;
    const t = this.now;
    const disc = {
      x: this.xAt(d, t),
      y: this.yAt(d, t),
      vx: this.vxAt(d, t),
      vy: this.vyAt(d, t),
      ax: m[d * 8 + 5] as number,
      ay: m[d * 8 + 6] as number,
      r: b.r[d] as number,
    };
    const R = b.r[p] as number;
    const margin = ZENO_TRAP_SLACK * disc.r;
    for (const end of sides) {
      const tStar = lineCloses(t, disc, m, p * 8, R, end.core, hull, corridor);
      if (Number.isNaN(tStar) || !this.pathClear(p, R, margin)) continue;
      strip[0] = corridor[0] as number;
      strip[1] = corridor[1] as number;
      strip[2] = corridor[2] as number;
      strip[3] = corridor[3] as number;
      strip[4] = corridor[2] as number;
      strip[5] = corridor[3] as number;
      if (!this.stripClear(p, end, disc.r + margin)) continue;
      throw new SimulationError(
        `body ${quoteId(b.ids[d] as string)} is crushed in line between the immovable body ${quoteId(b.ids[p] as string)} and ${named(end)}, which close on it by t=${tStar}: infinitely many collisions before then (a Zeno state: a disc crushed by an immovable body), which the exact model cannot pass`,
        t,
      );
    }
  }

  /**
   * Whether the stretch of line in `strip` keeps more than `reach` (plus their own radius) from
   * every line, point and immovable disc but slot p and the side `end`: the disc on it touches
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

  /** Whether the last sidesNear found no finite disc but d. */
  private alone = false;

  /**
   * The obstacles and immovable discs (other than p) nearest slot d, in canonical order, at most
   * ZENO_TRAP_CANDIDATES of them; null when another immovable body than p moves (its motion could
   * change what p runs into). Sets `alone`.
   */
  private sidesNear(d: number, p: number): Side[] | null {
    const b = this.store;
    const t = this.now;
    const x = this.xAt(d, t);
    const y = this.yAt(d, t);
    const r = b.r[d] as number;
    const kept: Side[] = [];
    for (const l of this.lineList) {
      const gap = coreDistance(fill(l.kind, l.x1, l.y1, l.x2, l.y2, 0), x, y) - r;
      keep(kept, gap, 0, l.id);
    }
    for (const q of this.pointList)
      keep(kept, coreDistance(fill("point", q.x, q.y, q.x, q.y, 0), x, y) - r, 1, q.id);
    this.alone = true;
    for (let s = 0; s < b.slotCount; s++) {
      const id = b.ids[s];
      if (id === undefined || s === p || s === d) continue;
      if (b.m[s] !== INF) {
        this.alone = false;
        continue;
      }
      if (this.isMoving(s)) return null;
      const qx = b.mot[s * 8 + 1] as number;
      const qy = b.mot[s * 8 + 2] as number;
      const rad = b.r[s] as number;
      keep(kept, coreDistance(fill("point", qx, qy, qx, qy, rad), x, y) - rad - r, 2, id);
    }
    return kept;
  }

  /**
   * Whether slot p's path (radius R) over the triangle in `hull` stays more than `margin` clear of
   * every line, point and immovable disc: it meets nothing that would change its motion.
   */
  private pathClear(p: number, R: number, margin: number): boolean {
    const b = this.store;
    for (const l of this.lineList)
      if (!(triangleCoreDistance(hull, fill(l.kind, l.x1, l.y1, l.x2, l.y2, 0)) > R + margin)) return false;
    for (const q of this.pointList)
      if (!(triangleCoreDistance(hull, fill("point", q.x, q.y, q.x, q.y, 0)) > R + margin)) return false;
    for (let s = 0; s < b.slotCount; s++) {
      if (b.ids[s] === undefined || s === p || b.m[s] !== INF) continue;
      const qx = b.mot[s * 8 + 1] as number;
      const qy = b.mot[s * 8 + 2] as number;
      const rad = b.r[s] as number;
      if (!(triangleCoreDistance(hull, fill("point", qx, qy, qx, qy, rad)) > R + rad + margin)) return false;
    }
    return true;
  }
}
