/**
 * TimelineObservers: the Timeline's observing half, between the reading half (TimelineReader, which
 * it extends) and the changes (Timeline, which extends it). A revision number that changes on every
 * change (`getSnapshot`) and the subscribers told after it (`subscribe`), the pair React's
 * useSyncExternalStore takes. Timeline calls `notifyChange()` after each change it made (apply,
 * setActions, prolong, forgetBefore); how the listeners are called, and what happens when one throws,
 * is listeners.ts.
 */
import { given } from "../sim/refusalText.js";
import type { TimelineCore } from "./core.js";
import { notifyAll } from "./listeners.js";
import { TimelineReader } from "./reader.js";

/** A TimelineReader with a revision number and subscribers (Timeline extends it). */
export class TimelineObservers extends TimelineReader {
  private revision = 0;
  private readonly listeners = new Set<() => void>();

  /** @internal */
  protected constructor(core: TimelineCore) {
    super(core);
  }

  /** @internal A new revision; every listener is told (listeners.ts). */
  protected notifyChange(): void {
    this.revision++;
    notifyAll(this.listeners);
  }

  /** Call `listener` after every change (apply, setActions, prolong). Returns the unsubscribe. A
   *  listener that throws does not stop the others; its error is rethrown after them. A listener
   *  that is not a function throws TypeError. */
  subscribe(listener: () => void): () => void {
    if (typeof listener !== "function")
      throw new TypeError(`subscribe(listener): must be a function (got ${given(listener)})`);
    this.listeners.add(listener);
    return () => {
      this.listeners.delete(listener);
    };
  }

  /** Revision number: changes on every change. */
  getSnapshot(): number {
    return this.revision;
  }
}
