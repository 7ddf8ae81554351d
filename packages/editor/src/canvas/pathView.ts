/**
 * PathView: the canvas's Path view. While it is on (uiStore `path`) and a body is selected, it keeps
 * that body's whole computed path (worker op `path`, remote/pathLine.ts) for the canvas to draw, and
 * asks again when the history changes (an edit, a computation going on: at most every
 * REFRESH_MS while the revision keeps changing, and never more than a tenth of the time when the
 * worker is busy with paths: one of a 10-million-event history takes it about 250 ms, review). An answer for an older selection or revision than
 * the latest asked is still shown until the next arrives (the path of the body a moment ago), but
 * never for another body. What it shows is published as uiStore `pathShown` (the toolbar says where
 * a long path was cut). A failed request clears the path and says why in the message bar.
 */
import type { Editor } from "../editor";
import { PATH_MAX_POINTS, type PathLine } from "../remote/pathLine";

/** Shortest interval between two path requests while the history keeps changing (ms). */
export const REFRESH_MS = 400;
/** The interval is at least this many times what the last request took, so that paths take at
 *  most a tenth of the worker while a computation runs. */
export const COST_FACTOR = 10;

export class PathView {
  /** What to draw (null: nothing). */
  line: PathLine | null = null;
  private lineId: string | null = null;
  /** `id revision` of the last request sent; "" for none. */
  private asked = "";
  private busy = false;
  private timer: ReturnType<typeof setTimeout> | null = null;
  private lastSent = -Infinity;
  /** How long the last request took to be answered (ms). */
  private lastCost = 0;
  private readonly offs: (() => void)[] = [];

  constructor(
    private readonly editor: Editor,
    private readonly redraw: () => void,
  ) {
    this.offs.push(editor.ui.subscribe(() => this.update()));
    this.offs.push(editor.client.subscribe(() => this.update()));
    this.update();
  }

  dispose(): void {
    for (const off of this.offs) off();
    if (this.timer !== null) clearTimeout(this.timer);
  }

  /** The body whose path is wanted, or null. */
  private wanted(): string | null {
    const s = this.editor.ui.getState();
    return s.path && s.selection?.kind === "body" ? s.selection.id : null;
  }

  private update(): void {
    const id = this.wanted();
    if (id !== this.lineId && this.line !== null) this.show(null, null);
    if (id === null) {
      this.asked = "";
      return;
    }
    const revision = this.editor.client.getSnapshot().revision;
    if (revision < 0) return;
    const key = `${id} ${revision}`;
    if (this.timer !== null && this.lineId !== id) {
      // another body: at once, not after the wait meant for this one
      clearTimeout(this.timer);
      this.timer = null;
    }
    if (key === this.asked || this.busy || this.timer !== null) return;
    const wait = this.lastSent + Math.max(REFRESH_MS, COST_FACTOR * this.lastCost) - performance.now();
    if (wait > 0 && this.lineId === id) {
      this.timer = setTimeout(() => {
        this.timer = null;
        this.update();
      }, wait);
      return;
    }
    this.send(id, key);
  }

  private send(id: string, key: string): void {
    this.asked = key;
    this.busy = true;
    this.lastSent = performance.now();
    const sent = performance.now();
    this.editor.client.path(id, PATH_MAX_POINTS).then(
      (line) => {
        this.busy = false;
        this.lastCost = performance.now() - sent;
        if (this.wanted() === id) this.show(id, line);
        this.update();
      },
      (e: unknown) => {
        this.busy = false;
        this.show(null, null);
        const text = `Path of ${id}: ${e instanceof Error ? e.message : String(e)}`;
        this.editor.ui.setState({ message: { text, tone: "error" } });
      },
    );
  }

  private show(id: string | null, line: PathLine | null): void {
    this.line = line;
    this.lineId = line === null ? null : id;
    const shown = line === null || id === null ? null : { id, cutAt: line.cutAt };
    const prev = this.editor.ui.getState().pathShown;
    if (prev?.id !== shown?.id || prev?.cutAt !== shown?.cutAt) this.editor.ui.setState({ pathShown: shown });
    this.redraw();
  }
}
