/**
 * EditorTime: the time controls of an Editor (editor.ts), over its EditorSession and EditorUndo: the current time
 * (kept within [0, horizon], or the end of a history being computed again), going to a typed time (computing up to it first when it lies past the
 * horizon), stepping from event to event (computing ahead to the next event past the horizon), play
 * and pause (saying why playback cannot start) and the playback speed. None of them is an edit:
 * nothing here is recorded in the undo history. Why playback cannot start (backwards from 0, at the
 * end of the history, at speed 0) is said until playback starts or the speed changes; speed 0 is a
 * speed one can set (the ±0.1 steps pass through it) but not play at: setting it while playing
 * pauses, and says so (playing at 0 showed Pause with nothing moving).
 */

import { shown } from "./editorSession";
import { EditorUndo } from "./editorUndo";
import { canExtend } from "./playback";
import { restoreTarget } from "./remote/protocol";
import type { Message } from "./store/uiStore";

export class EditorTime extends EditorUndo {
  /** The tail of the chain of event steps (see stepEvent). */
  private steps: Promise<void> = Promise.resolve();
  /** How many times the user cancelled a computation (Cancel): tells a cancelled one from one done. */
  private cancels = 0;
  /** The message play() or setSpeed() showed to say why playback does not run (see sayWhyNotPlaying). */
  private notPlaying: Message | null = null;

  /**
   * Moves the time to t, kept within [0, end]: the horizon, or while the history the user had is
   * computed again (an undo, an edit in the past) the end of that history, where the time is then
   * held until the recomputation reaches it (a slider dragged there once jumped back to the
   * recomputation's progress).
   */
  setTime(t: number): void {
    const info = this.client.getSnapshot();
    const end = Math.max(info.horizon, restoreTarget(info.computing));
    this.ui.setState({ t: Math.min(Math.max(t, 0), end) });
  }

  override cancelCompute(): void {
    this.cancels++;
    super.cancelCompute();
  }

  /**
   * Goes to time t (a typed time). Past the horizon it computes up to t first and then goes there
   * (cut to the horizon if that computation is cancelled, which is said, or refused). When the user
   * moves the time or edits the scene while it computes, the time stays where they are.
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
    const cancels = this.cancels;
    try {
      await this.client.compute({ time: t - h });
    } catch (e) {
      this.fail(e);
      return;
    }
    await this.whenComputed();
    if (this.ui.getState().t !== from || this.client.getSnapshot().docRevision !== docRevision) return;
    const horizon = this.client.getSnapshot().horizon;
    if (horizon < t && this.cancels !== cancels)
      this.info(`Computation cancelled at t = ${shown(horizon)} s; showing the end of the computed history.`);
    this.setTime(t);
  }

  /**
   * Resolves when the worker runs no computation, or earlier once `enough` holds (checked on every
   * change of the timeline and of the UI store).
   */
  private whenComputed(enough: () => boolean = () => false): Promise<void> {
    return new Promise((resolve) => {
      const check = () => {
        if (this.client.getSnapshot().computing !== null && !enough()) return;
        off();
        offUi();
        resolve();
      };
      const off = this.client.subscribe(check);
      const offUi = this.ui.subscribe(check);
      check();
    });
  }

  /**
   * Steps to the next or previous event and pauses; when there is none, says so. Steps run one after
   * another, each from the current time when it starts: where the previous step landed (quick
   * presses of → step one event each), or where the user has moved the time since. A step lands
   * only if the time and the scene did not change while it waited for the worker.
   */
  stepEvent(direction: 1 | -1): Promise<void> {
    const run = this.steps.then(() => this.step(direction));
    this.steps = run.catch(() => undefined);
    return run;
  }

  private async step(direction: 1 | -1): Promise<void> {
    const t = this.now();
    const docRevision = this.client.getSnapshot().docRevision;
    this.ui.setState({ playing: false });
    const moved = () => this.now() !== t || this.client.getSnapshot().docRevision !== docRevision;
    let next: number | null;
    try {
      next = direction > 0 ? await this.client.nextEvent(t) : await this.client.prevEvent(t);
      if (next === null && direction > 0 && !moved()) next = await this.eventAhead(t, moved);
    } catch (e) {
      this.fail(e);
      return;
    }
    if (moved()) return;
    if (next !== null) {
      // An earlier step's or Play's notice ("No event after …") no longer holds (it stayed up).
      const info = this.ui.getState().message?.tone === "info";
      this.ui.setState(info ? { t: next, message: null } : { t: next });
    } else if (direction < 0) this.info(`No event before t = ${shown(t)} s.`);
  }

  /**
   * The first event after t when none is computed up to the horizon: waits for a running
   * computation (until it logs an event after t), then computes ahead one event at a time (progress
   * and Cancel as for any computation) until one lies after t. Null when there is none, after saying
   * why (nothing more happens, the engine stopped, the computation was cancelled), or when the user
   * moved the time or edited the scene meanwhile (the caller checks).
   */
  private async eventAhead(t: number, moved: () => boolean): Promise<number | null> {
    const cancels = this.cancels;
    // Past the horizon (an undo's recomputation cancelled short of the time), the history is first
    // computed up to t in one job: one event per request took about an hour to cover 20 s of a
    // 20,000-disc gas.
    const start = this.client.getSnapshot();
    if (start.horizon < t && start.computing === null) await this.client.compute({ time: t - start.horizon });
    const enough = () => {
      const last = this.client.getSnapshot().lastEventTime;
      return moved() || (last !== null && last > t);
    };
    for (let running = this.client.getSnapshot().computing !== null; ; running = true) {
      if (running) {
        await this.whenComputed(enough);
        if (moved()) return null;
        const next = await this.client.nextEvent(t);
        if (next !== null) return next;
      }
      const info = this.client.getSnapshot();
      if (info.idle || info.stopped !== null || this.cancels !== cancels) break;
      // `events` counts collisions and stops from the horizon (actions before them are applied on
      // the way); events at the horizon's own time can take more than one round.
      await this.client.compute({ events: 1 });
    }
    const info = this.client.getSnapshot();
    const at = shown(t);
    const h = shown(info.horizon);
    if (info.stopped !== null)
      this.ui.setState({
        message: {
          text: `No event after t = ${at} s: the computation stopped at t = ${h} s: ${info.stopped}`,
          tone: "error",
        },
      });
    else if (info.idle) this.info(`No event after t = ${at} s: nothing more happens in this scene.`);
    else this.info(`No event after t = ${at} s up to t = ${h} s: the computation was cancelled.`);
    return null;
  }

  /** Plays or pauses. */
  togglePlay(): void {
    if (this.ui.getState().playing) this.ui.setState({ playing: false });
    else this.play();
  }

  /** Shows why playback does not run; it goes once playback starts or the speed changes. */
  private sayWhyNotPlaying(text: string): void {
    this.notPlaying = { text, tone: "info" };
    this.ui.setState({ message: this.notPlaying });
  }

  /** Removes the message saying why playback did not run, if it is still shown. */
  private forgetWhyNotPlaying(): void {
    if (this.notPlaying !== null && this.ui.getState().message === this.notPlaying)
      this.ui.setState({ message: null });
    this.notPlaying = null;
  }

  /** Starts playback at the current speed; says why when it would stop at once, or not move. */
  play(): void {
    const s = this.ui.getState();
    if (s.speed === 0) {
      this.sayWhyNotPlaying("Speed 0: nothing would move. Set a speed (Speed field, 1×) to play.");
      return;
    }
    // Backwards from 0 the playback clock (playback.ts) stops at the first frame: it did nothing.
    if (s.speed < 0 && s.t <= 0) {
      this.sayWhyNotPlaying(
        "Playing backwards from t = 0: nothing before it. Set a positive speed to play forwards.",
      );
      return;
    }
    // Forwards from the end of the history with nothing to compute further, it stopped at once too.
    const info = this.client.getSnapshot();
    if (
      s.speed > 0 &&
      s.t >= info.horizon &&
      info.computing === null &&
      !canExtend(s.calc.autoExtend, info)
    ) {
      const end = shown(info.horizon);
      const why =
        info.stopped !== null
          ? "the computation stopped there"
          : info.idle
            ? "no event is left to compute (type a later time to go further)"
            : "auto-extend is off (Calculation panel)";
      this.sayWhyNotPlaying(`At the end of the computed history (t = ${end} s): ${why}.`);
      return;
    }
    this.forgetWhyNotPlaying();
    this.ui.setState({ playing: true });
  }

  /** Sets the speed (kept to 0.001); 0 while playing pauses, and says so. */
  setSpeed(speed: number): void {
    if (!Number.isFinite(speed)) return;
    const next = Math.round(speed * 1000) / 1000;
    const s = this.ui.getState();
    if (next === s.speed) return;
    this.forgetWhyNotPlaying();
    this.ui.setState({ speed: next });
    if (next === 0 && s.playing) {
      this.ui.setState({ playing: false });
      this.sayWhyNotPlaying("Speed 0: paused. Set a speed (Speed field, 1×) to play again.");
    }
  }
}
