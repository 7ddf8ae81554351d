/**
 * ChainIndex: what a read of a delta keyframe needs of its chain (keyframeChain.ts says what a chain
 * is), built once per chain and extended as deltas are added to it; a ChainCache (keyframeChain.ts)
 * keeps the last few a Timeline used.
 * - `members`, the chain's keyframes by depth (depth 0 the full keyframe): a read walks an array,
 *   not the `prev` links;
 * - `order`, every body number the chain ever holds (the full keyframe's and every delta's `added`)
 *   sorted by id, each delta's `added` merged in once, and per body number the depth it joined at
 *   (`born`) and the depth it was removed at (`died`). The order of a keyframe at depth d is then
 *   mapOrder(d): the chain order filtered to born <= d < died, one pass with no id comparison (it
 *   was a sort of every body added since the full keyframe, at every read).
 * It holds 12 bytes per body and references to its members (history the Timeline holds anyway).
 */
import type { Keyframe, KeyframeArrays, KeyframeDelta } from "./keyframe.js";
import { mergeById } from "./keyframeDelta.js";

/** `died` of a body never removed in the chain. */
const NEVER = 0x7fffffff;

export class ChainIndex {
  readonly members: Keyframe[];
  readonly depth = new Map<Keyframe, number>();
  /** the chain order (see the header) of the members up to depth `orderedTo`, made on demand */
  private order: Uint32Array | null = null;
  private orderedTo = 0;
  private born = new Int32Array(0);
  private died = new Int32Array(0);

  constructor(members: readonly Keyframe[]) {
    this.members = [];
    this.extend(members);
  }

  get tip(): number {
    return this.members.length - 1;
  }

  /** Append `more` (each the `prev` of the next, the first one's the tip's successor). */
  extend(more: readonly Keyframe[]): void {
    for (const kf of more) {
      this.depth.set(kf, this.members.length);
      this.members.push(kf);
    }
  }

  /** The bodies live at depth d, sorted by id (see the header; `ids[n]` names body n). */
  mapOrder(d: number, ids: readonly string[]): Uint32Array {
    this.mergeAdded(ids);
    const { born, died } = this;
    const order = this.order as Uint32Array;
    const out = new Uint32Array(order.length);
    let count = 0;
    for (let k = 0; k < order.length; k++) {
      const n = order[k] as number;
      if ((born[n] as number) <= d && (died[n] as number) > d) out[count++] = n;
    }
    return count === out.length ? out : out.slice(0, count);
  }

  /** Bring `order`, `born` and `died` up to the tip: one merge of every body added since. */
  private mergeAdded(ids: readonly string[]): void {
    if (this.order !== null && this.orderedTo === this.tip) return;
    const bodyCount = (this.members[this.tip] as Keyframe).bodyCount;
    if (bodyCount > this.born.length) {
      const born = new Int32Array(bodyCount);
      const died = new Int32Array(bodyCount).fill(NEVER);
      born.set(this.born);
      died.set(this.died);
      this.born = born;
      this.died = died;
    }
    if (this.order === null) {
      this.order = ((this.members[0] as Keyframe).full as KeyframeArrays).order;
      for (const n of this.order) this.born[n] = 0;
    }
    const added: number[] = [];
    for (let d = this.orderedTo + 1; d <= this.tip; d++) {
      const delta = (this.members[d] as Keyframe).delta as KeyframeDelta;
      for (const n of delta.added) {
        this.born[n] = d;
        added.push(n);
      }
      for (const n of delta.removed) this.died[n] = d;
    }
    this.orderedTo = this.tip;
    if (added.length > 0) this.order = mergeById(this.order, added, ids);
  }
}
