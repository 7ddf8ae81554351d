/**
 * EditorTime: the time controls of an Editor (editor.ts), over its EditorSession: the current time
 * (kept within [0, horizon]), going to a typed time (computing up to it first when it lies past the
 * horizon), stepping from event to event, play/pause and the playback speed. None of them is an edit:
 * nothing here is recorded in the undo history.
 */

import { EditorSession } from "./editorSession";

export class EditorTime extends EditorSession {
  setTime(t: number): void {
    const h = this.client.getSnapshot().horizon;
    this.ui.setState({ t: Math.min(Math.max(t, 0), h) });
  }

  /**
   * Goes to time t (a typed time). Past the horizon it computes up to t first and then goes there
   * (cut to the horizon if that computation is cancelled or refused). When the user moves the time
   * or edits the scene while it computes, the time stays where they are.
   */
  async goTo(t: number): Promise<void> {
    const h = this.client.getSnapshot().horizon;
    if (!(t > h)) {
      this.setTime(t);
      return;
    }
    this.ui.setState({ playing: false });
    const from = this.ui.getState().t;
    const docRevision = this.client.getSnapshot().docRevision;
    try {
      await this.client.compute({ time: t - h });
    } catch (e) {
      this.fail(e);
      return;
    }
    await this.whenComputed();
    if (this.ui.getState().t !== from || this.client.getSnapshot().docRevision !== docRevision) return;
    this.setTime(t);
  }

  /** Resolves when the worker runs no computation. */
  private whenComputed(): Promise<void> {
    return new Promise((resolve) => {
      const check = () => {
        if (this.client.getSnapshot().computing !== null) return;
        off();
        resolve();
      };
      const off = this.client.subscribe(check);
      check();
    });
  }

  /** Steps to the next or previous event; when there is none, says so. */
  async stepEvent(direction: 1 | -1): Promise<void> {
    const t = this.now();
    const next = direction > 0 ? await this.client.nextEvent(t) : await this.client.prevEvent(t);
    if (next !== null) this.ui.setState({ t: next, playing: false });
    else {
      const at = Number(t.toPrecision(6));
      const h = Number(this.client.getSnapshot().horizon.toPrecision(6));
      this.info(
        direction > 0
          ? `No event after t = ${at} s up to the computed horizon (${h} s).`
          : `No event before t = ${at} s.`,
      );
    }
  }

  togglePlay(): void {
    const s = this.ui.getState();
    this.ui.setState({ playing: !s.playing });
  }

  setSpeed(speed: number): void {
    if (!Number.isFinite(speed)) return;
    this.ui.setState({ speed: Math.round(speed * 1000) / 1000 });
  }
}
