/**
 * The Zeno guard: each collision or stop about to be processed is counted in the Zeno watch
 * (zenoWatch.ts) and, for a stop, in its push watch (pushWatch.ts), which throw a SimulationError
 * on a state the exact model cannot pass; a collision with a moving immovable disc may first be
 * tried by the trap watch (trapWatch.ts), which proves a crush geometrically. Here the World tells
 * them what they cannot see for themselves: whether an immovable body moves, whether a stopping
 * body moved at all, the masses of the bodies in the event (a long burst at one instant among very
 * different masses is finite), and, for a report only, who the Zeno state caught (zenoCaught.ts:
 * the event's bodies and its line or point, named, and the bodies and obstacles touching them).
 */
import { ZENO_TRAP_EVERY, ZENO_TRAP_TRIES } from "../tolerances.js";
import { EV_BODY, EV_LINE, EV_STOP } from "./bodyStore.js";
import type { Line, Point } from "./obstacles.js";
import { quoteId } from "./refusalText.js";
import { TrapWatch } from "./trapWatch.js";
import type { ZenoCulprits } from "./zenoAdvice.js";
import { type CaughtView, caught } from "./zenoCaught.js";

export class ZenoGuard extends TrapWatch {
  /**
   * Count the event about to be processed now in the Zeno watch (throws on a Zeno state); `before`
   * is the World's time before it (equal to now: at the same instant as the previous item).
   */
  protected guardZeno(before: number, s: number, kind: number): void {
    this.guarded = s;
    // Every watch tests before any counts (the trap watch counts nothing): an event they refuse
    // leaves the counters as they were. The response's own refusal (a disc resting on an
    // obstacle) is tested before this.
    const unmoved = kind === EV_STOP && this.stopsUnmoved(s);
    if (unmoved) this.zeno.push.check(this.store.ids[s] as string, true, this.now);
    const b = this.store;
    // The trap watch's proof is tried at some collisions only (ZENO_TRAP_EVERY): tested here, so
    // that the other collisions pay no call.
    if (kind === EV_BODY && (this.zeno.windowEvents & (ZENO_TRAP_EVERY - 1)) < ZENO_TRAP_TRIES)
      this.guardTrap(s, b.evOther[s] as number);
    this.zeno.check(
      this.now,
      before,
      Math.max(1, b.slotCount),
      this.pumps,
      this.culprits,
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

  /** Slot of the event being counted, for a Zeno report (no allocation per event). */
  private guarded = -1;

  /** Who the Zeno state met at the guarded event caught (zenoCaught.ts); called only to report it. */
  private readonly culprits = (since: number): ZenoCulprits => {
    const b = this.store;
    const s = this.guarded;
    const kind = b.evKind[s] as number;
    const other = b.evOther[s] as number;
    const id = quoteId(b.ids[s] as string);
    const view: CaughtView = {
      store: b,
      lines: this.lineList,
      points: this.pointList,
      x: (q) => this.xAt(q, this.now),
      y: (q) => this.yAt(q, this.now),
      moving: (q) => this.isMoving(q),
    };
    if (kind === EV_BODY)
      return caught(
        view,
        { slots: [s, other], obstacle: null, last: `${id} and ${quoteId(b.ids[other] as string)}` },
        since,
      );
    if (kind === EV_STOP) return caught(view, { slots: [s], obstacle: null, last: `${id} stopping` }, since);
    const line = kind === EV_LINE;
    const obstacle = line ? (this.lineList[other] as Line).id : (this.pointList[other] as Point).id;
    const last = `${id} and ${line ? "line" : "point"} ${quoteId(obstacle)}`;
    return caught(view, { slots: [s], obstacle: { line, id: obstacle }, last }, since);
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
