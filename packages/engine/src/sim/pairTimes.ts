/**
 * Pair times: when bodies s and o first touch, from the two motions alone (solved from the later of
 * their start times), so a time gives the same bits whenever and from whichever side it is
 * computed; the last pair solved is remembered for the second body of a collision. A pure query of
 * the state: nothing is offered or queued here (candidates.ts keeps the earliest contact).
 */
import { discDiscTimeScaled } from "../physics/timeOfImpact.js";
import { BroadPhase } from "./broadPhase.js";

const INF = Number.POSITIVE_INFINITY;
const INF_NEG = Number.NEGATIVE_INFINITY;

export class PairTimes extends BroadPhase {
  /**
   * Earliest contact time of bodies s and o, or +Infinity. The result is symmetric (it depends
   * only on the two motions), so the last pair solved is remembered: after a collision both
   * participants are re-predicted and the second would solve the same pair again. The plain grid's
   * cell scan (candidates.ts scanCell) calls solvePair directly: there the memo cost more than it saved.
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
    this.solvePair(s, o);
    this.memoS = s;
    this.memoO = o;
    this.memoVS = vs;
    this.memoVO = vo;
    this.memoTime = this.now;
    this.memoResult = this.pairResult;
    return this.memoResult;
  }

  private memoS = -1;
  private memoO = -1;
  private memoVS = -1;
  private memoVO = -1;
  private memoTime = Number.NaN;
  private memoResult = INF;
  /** What the last solvePair found (its result: see there). */
  protected pairResult = INF;

  /**
   * Solve the pair into `pairResult`. Not returned: V8 boxes a double that a call it does not
   * inline returns (a heap allocation per pair test), and a double field is written in place.
   */
  protected solvePair(s: number, o: number): void {
    const b = this.store;
    const m = b.mot;
    // Record offsets as s << 3 and fields as i | k: integer operations V8 compiles without the
    // overflow checks of s * 8 + k (a slot is far below 2^28).
    const i = s << 3;
    const j = o << 3;
    const ts = m[i] as number;
    const to = m[j] as number;
    const ends = m[i | 7] as number;
    const endo = m[j | 7] as number;
    // Path boxes are finite only for motions that end (friction) or rest: when s's box is
    // unbounded the boxes cannot be disjoint, and the partner's box is not even loaded (nor the
    // switch, read last).
    if ((b.boxMaxX[s] as number) < INF && this.opt.pathBounds === true) {
      if (
        (b.boxMinX[s] as number) > (b.boxMaxX[o] as number) ||
        (b.boxMinX[o] as number) > (b.boxMaxX[s] as number) ||
        (b.boxMinY[s] as number) > (b.boxMaxY[o] as number) ||
        (b.boxMinY[o] as number) > (b.boxMaxY[s] as number)
      ) {
        this.pairResult = INF;
        return;
      }
    }
    const tb = Math.max(ts, to);
    const hi = Math.min(ends, endo) - tb;
    const vxs0 = m[i | 3] as number;
    const vys0 = m[i | 4] as number;
    const vxo0 = m[j | 3] as number;
    const vyo0 = m[j | 4] as number;
    const axs = m[i | 5] as number;
    const ays = m[i | 6] as number;
    const axo = m[j | 5] as number;
    const ayo = m[j | 6] as number;
    // positionAt and velocityAt (motion.ts) by hand, the same operations: each imported function
    // V8 inlines costs a load of its module cell, a check that it is initialised and one that it is
    // still the same function, about 12 instructions per pair test for the two.
    const dts = tb - ts;
    const dto = tb - to;
    const dx =
      (m[j | 1] as number) +
      dto * (vxo0 + 0.5 * axo * dto) -
      ((m[i | 1] as number) + dts * (vxs0 + 0.5 * axs * dts));
    const dy =
      (m[j | 2] as number) +
      dto * (vyo0 + 0.5 * ayo * dto) -
      ((m[i | 2] as number) + dts * (vys0 + 0.5 * ays * dts));
    const vxs = vxs0 + axs * dts;
    const vys = vys0 + ays * dts;
    const vxo = vxo0 + axo * dto;
    const vyo = vyo0 + ayo * dto;
    const ux = vxo - vxs;
    const uy = vyo - vys;
    // Cheap rejection before any solve: with no relative acceleration a receding pair never meets.
    if (axo === axs && ayo === ays && dx * ux + dy * uy >= 0 && this.opt.recedingReject === true) {
      this.pairResult = INF;
      return;
    }
    const R = (b.r[s] as number) + (b.r[o] as number);
    const tau = discDiscTimeScaled(
      dx,
      dy,
      ux,
      uy,
      axo - axs,
      ayo - ays,
      R,
      this.now - tb,
      hi,
      this.opt.quadraticFastPath === true,
      // Each component's two bodies added first, so the scales have the same bits from either side
      // (review: summed left to right, the two orders differed by an ulp, and so did a verdict).
      Math.abs(dx) * (Math.abs(vxs) + Math.abs(vxo)) + Math.abs(dy) * (Math.abs(vys) + Math.abs(vyo)),
      Math.abs(dx) * (Math.abs(axs) + Math.abs(axo)) + Math.abs(dy) * (Math.abs(ays) + Math.abs(ayo)),
      INF_NEG, // two discs never rest on each other (a field accelerates both alike)
    );
    this.pairResult = tau === INF ? INF : Math.max(tb + tau, this.now);
  }
}
