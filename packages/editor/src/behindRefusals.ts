/**
 * Refusals of an edit at a time the history has not reached yet. After an undo, a redo or a rename
 * the history is recomputed from the start while the current time stays; until it gets there the
 * canvas and the tables show the end of the history, and an edit would be built from those values,
 * so it is refused (behindMessage: "still being computed", or "cancelled" when the computation
 * stopped short). Such a refusal holds only while the history is short of the edit's time: the
 * refusal shown in a cell stayed until the user pressed Enter again, long after the computation had
 * got there. BehindRefusals keeps the refusals given and says when each one lapses (the history
 * reached its time: null) or changes (the computation stopped short, or started again: the refusal
 * that now holds), so the cell and the message bar stop showing what is no longer true. The edit
 * itself is never applied later on its own: as every refused edit (a change taken back after its
 * check, pendingEdit.ts) it is the user's to make again (the cell keeps its draft for Enter).
 */

/** A time as messages write it (6 significant digits). */
const shown = (t: number): number => Number(t.toPrecision(6));

/**
 * Why an edit at time `late` must wait, or null when the history (up to `horizon`) holds that time.
 * `computing`: a computation runs (it will get there), else it was cancelled short of it.
 */
export function behindMessage(late: number, horizon: number, computing: boolean): string | null {
  if (!(late > horizon)) return null;
  const at = shown(late);
  const now = shown(horizon);
  if (!computing)
    return `The history reaches only t = ${now} s (its computation was cancelled): go to a computed time, or type t = ${at} s to compute up to it, then edit.`;
  return `The history is still being computed up to t = ${at} s (it reaches ${now} s): edit once it gets there.`;
}

/** What the message bar says when a refusal lapses: the history reached the time of `late`. */
export function reachedMessage(late: number): string {
  return `The history has reached t = ${shown(late)} s: edits there are accepted now.`;
}

/** The part of the TimelineClient's snapshot the refusals follow. */
export interface HistorySource {
  getSnapshot(): { horizon: number; computing: unknown };
  subscribe(listener: () => void): () => void;
}

interface Refusal {
  /** The edit's time. */
  time: number;
  /** Whether a computation ran when it was given (its wording says which). */
  computing: boolean;
  /** Waiting for its lapse or change (whenChanged). */
  waiters: ((next: string | null) => void)[];
}

export class BehindRefusals {
  /** The refusals given that may still hold, by their text. */
  private readonly given = new Map<string, Refusal>();

  /** `changed(text, next, time)`: the refusal `text` of an edit at `time` lapsed (next null) or now reads `next`. */
  constructor(
    private readonly source: HistorySource,
    private readonly changed: (text: string, next: string | null, time: number) => void = () => {},
  ) {
    source.subscribe(() => this.follow());
  }

  /** The refusal of an edit at `late` now (null: none, the history holds it), kept to be followed. */
  refuse(late: number): string | null {
    const info = this.source.getSnapshot();
    const computing = info.computing !== null;
    const text = behindMessage(late, info.horizon, computing);
    if (text !== null && !this.given.has(text)) this.given.set(text, { time: late, computing, waiters: [] });
    return text;
  }

  /**
   * When the refusal `text` lapses (resolves to null: the history reached its time) or changes (to
   * the refusal that holds then); null when `text` is no refusal followed here.
   */
  whenChanged(text: string): Promise<string | null> | null {
    const r = this.given.get(text);
    if (r === undefined) return null;
    return new Promise((resolve) => r.waiters.push(resolve));
  }

  private follow(): void {
    if (this.given.size === 0) return;
    const info = this.source.getSnapshot();
    const computing = info.computing !== null;
    for (const [text, r] of [...this.given]) {
      if (info.horizon < r.time && computing === r.computing) continue;
      this.given.delete(text);
      const next = info.horizon < r.time ? this.refuse(r.time) : null;
      this.changed(text, next, r.time);
      for (const w of r.waiters) w(next);
    }
  }
}
