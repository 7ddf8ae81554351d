/**
 * The Zeno guard: each collision or stop about to be processed is counted in the Zeno watch
 * (zenoWatch.ts) and, for a stop, in its push watch (pushWatch.ts), which throw a SimulationError
 * on a state the exact model cannot pass. Here the World tells them what they cannot see for
 * themselves: whether an immovable body moves, whether a stopping body moved at all, the masses of the
 * bodies in the event (a long burst at one instant among very different masses is finite), and
 * which bodies the event is about (for the message).
 */
import { EV_BODY, EV_STOP } from "./bodyStore.js";
import { CellCrossings } from "./cellCrossings.js";

export class ZenoGuard extends CellCrossings {
  /**
   * Count the event about to be processed now in the Zeno watch (throws on a Zeno state); `before`
   * is the World's time before it (equal to now: at the same instant as the previous item).
   */
  protected guardZeno(before: number, s: number, kind: number): void {
    this.guarded = s;
    // Both watches test before either counts: an event they refuse leaves the counters as they
    // were. The response's own refusal (a disc resting on an obstacle) is tested before this.
    const unmoved = kind === EV_STOP && this.stopsUnmoved(s);
    if (unmoved) this.zeno.push.check(this.store.ids[s] as string, true, this.now);
    const b = this.store;
    this.zeno.check(
      this.now,
      before,
      Math.max(1, b.slotCount),
      this.pumps,
      this.describeGuarded,
      kind === EV_STOP ? Number.POSITIVE_INFINITY : (b.m[s] as number),
      kind === EV_BODY ? (b.m[b.evOther[s] as number] as number) : Number.POSITIVE_INFINITY,
    );
    if (kind === EV_STOP) this.zeno.push.stop(this.store.ids[s] as string, unmoved, this.now);
  }

  /** Whether body s, stopping now, is where its motion started, to the bit (a micro-stop). */
  private stopsUnmoved(s: number): boolean {
    const b = this.store;
    return this.xAt(s, this.now) === b.mot[s * 8 + 1] && this.yAt(s, this.now) === b.mot[s * 8 + 2];
  }

  private readonly pumps = (): boolean => this.pumpsEnergy();

  /** Slot of the event being counted, and its description for a Zeno message (no allocation per event). */
  private guarded = -1;
  private readonly describeGuarded = (): string => {
    const b = this.store;
    const s = this.guarded;
    const kind = b.evKind[s] as number;
    const id = `'${b.ids[s] as string}'`;
    if (kind === EV_BODY) return `${id} and '${b.ids[b.evOther[s] as number] as string}'`;
    if (kind === EV_STOP) return `${id} stopping`;
    return `${id} and an obstacle`;
  };

  /**
   * Whether an immovable (infinite-mass) body is moving: the only way elastic collisions can feed
   * energy in without bound, which a run of events converging on a finite time needs.
   */
  private pumpsEnergy(): boolean {
    const b = this.store;
    for (let s = 0; s < b.slotCount; s++)
      if (b.ids[s] !== undefined && b.m[s] === Number.POSITIVE_INFINITY && this.isMoving(s)) return true;
    return false;
  }
}
