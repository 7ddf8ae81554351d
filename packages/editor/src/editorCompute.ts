/**
 * EditorCompute: the base of EditorSession (editorSession.ts): the TimelineClient (the scene lives
 * in the worker's Timeline) and the UI store, the messages shown in it, and computing ahead. Methods
 * that can fail show the engine's message in the UI (fail; an edit, rewrite or rename refused
 * because a later action would become invalid, the engine's path `actions[i]`, also says which
 * action that is: failNaming, doc/actionRefs.ts; the edited action's own path is named as the
 * user's cell: doc/refusalTerms.ts). After each change the session computes ahead as
 * the Calculation settings say (computeUntil, ensureAhead), a reload at the current time computes at
 * least up to it (keepTo), and a computation the engine refused to continue (a Zeno state) is said.
 * Edits past the computed history are refused until it gets there (notComputedYet), a refusal that
 * lapses then (behindRefusals.ts: the message bar says so, a cell showing it drops it).
 */

import { BehindRefusals, reachedMessage } from "./behindRefusals";
import { explainRefusal, namedRefusal } from "./doc/actionRefs";
import { refusalInUserTerms } from "./doc/refusalTerms";
import type { Action, SceneFile, Until } from "./engineTypes";
import type { TimelineClient } from "./remote/client";
import type { TimelineInfo } from "./remote/protocol";
import type { UiStore } from "./store/uiStore";

/** A time as messages write it (6 significant digits). */
export const shown = (t: number): number => Number(t.toPrecision(6));

/** Where the author finds a refused action of the scene (panels/RefusedActionRow.tsx). */
export const REFUSED_ACTION_HINT =
  "The Event log lists it as refused: its ✕ removes it, its cells change it.";

/**
 * Why the computation stopped, after "The computation stopped at t = … s: ": the engine's message,
 * an action it refused named as the author knows it (doc/actionRefs.ts namedRefusal) and where
 * to remove or change it.
 */
export function stopMessage(info: Pick<TimelineInfo, "stopped" | "stoppedPath" | "doc">): string {
  const stopped = info.stopped ?? "";
  const named = namedRefusal(stopped, info.stoppedPath, info.doc?.actions ?? []);
  return named === stopped ? stopped : `${named}. ${REFUSED_ACTION_HINT}`;
}

export class EditorCompute {
  /** The refusals of edits the history has not reached yet, followed until they lapse. */
  private readonly behind: BehindRefusals;

  constructor(
    readonly client: TimelineClient,
    readonly ui: UiStore,
  ) {
    // A refusal the message bar still shows is replaced once it lapses or changes: by what the
    // edit meets now (the history reached its time), or the refusal that holds instead.
    this.behind = new BehindRefusals(client, (text, next, time) => {
      if (this.ui.getState().message?.text !== text) return;
      const message =
        next === null
          ? { text: reachedMessage(time), tone: "info" as const }
          : { text: next, tone: "error" as const };
      this.ui.setState({ message });
    });
    // A computation the engine refused to continue (a Zeno state, an action refused): say why the
    // horizon stops there, a refused action named by what it does, not by its index. An information still shown stays before it ("Opened late.json. Undo
    // returns to the scene you had before."): replaced, the author would no longer read that a
    // file was opened over the scene, nor how to get the scene back.
    let stopped: string | null = null;
    client.subscribe(() => {
      const info = client.getSnapshot();
      if (info.stopped === stopped) return;
      stopped = info.stopped;
      if (stopped === null) return;
      const h = shown(info.horizon);
      const said = this.ui.getState().message;
      const before = said?.tone === "info" ? `${said.text} ` : "";
      this.ui.setState({
        message: {
          text: `${before}The computation stopped at t = ${h} s: ${stopMessage(info)}`,
          tone: "error",
        },
      });
    });
  }

  get doc(): SceneFile {
    return this.client.getSnapshot().doc!;
  }

  protected fail(e: unknown): string {
    const text = e instanceof Error ? e.message : String(e);
    this.ui.setState({ message: { text, tone: "error" } });
    return text;
  }

  /**
   * fail, the message saying which action the engine's `actions[i]` is; `actions` is the list its
   * index refers to (the scene before an edit, the scene given to a load). `edited`: the one action
   * of a refused edit, whose engine path (`action.v[0]`) is then named as the user's cell ("A vx").
   */
  protected failNaming(e: unknown, actions: readonly Action[], edited?: Action): string {
    const raw = e instanceof Error ? e.message : String(e);
    const p = (e as { path?: unknown } | null)?.path;
    const path = typeof p === "string" ? p : null;
    const text = edited === undefined ? raw : refusalInUserTerms(raw, path, edited);
    return this.fail(explainRefusal(text, path, actions));
  }

  /** fail, an action the engine's `actions[i]` names said as the author knows it (a load's refusal). */
  protected failNamed(e: unknown, actions: readonly Action[]): string {
    const p = (e as { path?: unknown } | null)?.path;
    return this.fail(
      namedRefusal(e instanceof Error ? e.message : String(e), typeof p === "string" ? p : null, actions),
    );
  }

  info(text: string): void {
    this.ui.setState({ message: { text, tone: "info" } });
  }

  /** The current time (the UI store's). */
  protected now(): number {
    return this.ui.getState().t;
  }

  /** What "compute ahead" means with the current Calculation settings (null: until idle). */
  computeUntil(): Until | null {
    const c = this.ui.getState().calc;
    const u: Until = {};
    if (c.useTime) u.time = c.seconds;
    if (c.useEvents) u.events = c.events;
    return c.useTime || c.useEvents ? u : null;
  }

  computeAhead(): Promise<void> {
    return this.client.compute(this.computeUntil()).catch((e) => {
      this.fail(e);
    });
  }

  /**
   * After an edit: computes ahead of the current time, the Calculation panel's seconds counted from
   * it, not from the horizon. The horizon is then the later of the old one (the host brings the
   * history after an edit in the past back) and the current time plus those seconds: counted from
   * the horizon, by then the old one again, every edit pushed it that much further (audit).
   */
  protected async ensureAhead(): Promise<void> {
    const c = this.ui.getState().calc;
    const now = this.now();
    const h = this.client.getSnapshot().horizon;
    if (c.useTime && !c.useEvents && h >= now + c.seconds) return;
    const until = this.computeUntil();
    await this.client.compute(until, false, until?.time === undefined ? undefined : now).catch((e) => {
      this.fail(e);
    });
  }

  /**
   * How far a reload at the current time (undo, redo, rename, restart) must compute at least: the
   * current time, and the Calculation panel's seconds past it. The host also brings back the
   * history the scene had before the load (protocol.ts, `load`'s keepTo).
   */
  protected keepTo(): number {
    const c = this.ui.getState().calc;
    return this.now() + (c.useTime ? c.seconds : 0);
  }

  /** After a reload at the current time: computes ahead when the host had nothing to bring back. */
  protected afterReload(): Promise<void> {
    const info = this.client.getSnapshot();
    return info.computing === null && info.horizon === 0 ? this.computeAhead() : Promise.resolve();
  }

  cancelCompute(): void {
    this.client.cancel().catch((e) => this.fail(e));
  }

  /**
   * Why edits at these times must wait, or null. After an undo, a redo or a rename the history is
   * recomputed from the start while the current time stays; until the computation reaches it, the
   * canvas and the tables show the state at the horizon, not at the current time, and an edit would
   * be built from those values (a velocity typed in one cell keeps the other component shown).
   * The refusal is followed until it lapses (behindRefusals.ts; refusalChanged).
   */
  protected notComputedYet(actions: Action[]): string | null {
    return this.behind.refuse(Math.max(...actions.map((a) => a.time)));
  }

  /**
   * When the refusal `text` an edit got stops holding: null once the history has reached the edit's
   * time (the edit can be made again), or the refusal that holds instead (the computation stopped
   * short of it). No promise (null) for any other refusal: it holds until the edit changes. A cell
   * showing `text` follows it (panels/EditableCell.tsx).
   */
  refusalChanged(text: string): Promise<string | null> | null {
    return this.behind.whenChanged(text);
  }
}
