/**
 * Editor: the one object that turns user intentions into timeline requests. It is built in layers:
 * EditorCompute (editorCompute.ts: the TimelineClient, the UI store, messages, computing ahead),
 * EditorSession (editorSession.ts: the undo history, loading, edits as undo steps; its queue of
 * changes in sceneChanges.ts), EditorRewrites (editorRewrites.ts: the scene's meta, rewrites and
 * renames), EditorUndo (editorUndo.ts: undo and redo, also while an edit is checked), EditorTime
 * (editorTime.ts: the current time, go to, event steps, play and speed) and,
 * here, the edits at the current time: every edit is an
 * action stamped with the current time (add, move, strike, update, delete, clear), and the removal
 * of one action of any time (an Event-log entry's). An edit of an object (move, velocity, update,
 * globals) right after an action of that object at the same time is merged into it
 * (doc/mergeEdit.ts): x, then y, then r of a body at t = 2 are one action, still three undo steps. Methods that can fail resolve to the engine's
 * message (null on success) and show it in the UI; each that succeeds says what it did (an add what
 * it added and where, an edit the values it set and what Undo restores: doc/editConfirm.ts).
 */

import { strikeVelocity } from "./canvas/pointerPlace";
import { actionName, describeEntry } from "./doc/actionRefs";
import { confirmEdit, type FieldEdit, stateBefore } from "./doc/editConfirm";
import { nextFreeId } from "./doc/ids";
import { withActionChanged } from "./doc/refusedAction";
import { type ActionEntry, withoutAction } from "./doc/removeAction";
import type { ObjectKind } from "./doc/rename";
import { saveNameFor } from "./doc/saveName";
import { metaWithTitle, titleOf } from "./doc/sceneTitle";
import { shown } from "./editorSession";
import { EditorTime } from "./editorTime";
import type { Action, SceneFile, Vec2 } from "./engineTypes";
import { droppedNote, type OpenDraft } from "./openDrafts";
import type { TimelineClient } from "./remote/client";
import type { Frame } from "./remote/protocol";
import { dropStaleHighlight } from "./store/highlightGuard";
import { dropStaleSelection } from "./store/selectionGuard";
import { keepTimeWindow } from "./store/timeWindowGuard";
import type { UiStore } from "./store/uiStore";

/** Velocity given by a cue strike, per world unit of offset between the click and the disc centre (1/s). */
export const STRIKE_RATE = 4;

/** A cue click at a disc's very centre: the strike goes away from the click, so it has no direction. */
export const NO_STRIKE_DIRECTION =
  "Not struck: the cue strikes a disc away from the click, so click off its centre (the farther, the harder).";

/** "(3, -0.5)": a place as messages write it. */
const point = (p: Vec2): string => `(${shown(p[0])}, ${shown(p[1])})`;
/** `text`, then what it says of the drafts `dropped` with their object (openDrafts.ts), if any. */
const withDropped = (text: string, dropped: readonly OpenDraft[]): string =>
  dropped.length === 0 ? text : `${text} ${droppedNote(dropped)}`;
/** The object an add of this type makes: removing the add takes the object, and its drafts, away. */
const ADDED_KIND: Record<string, ObjectKind> = { addBody: "body", addLine: "line", addPoint: "point" };
/** ", at t = 3.2 s" for an object added after the start; nothing at t = 0. */
const when = (t: number): string => (t === 0 ? "" : `, at t = ${shown(t)} s`);

export const EMPTY_SCENE: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [],
};

export class Editor extends EditorTime {
  constructor(client: TimelineClient, ui: UiStore) {
    super(client, ui);
    // A selection whose object an undo, a load or a rewrite removed is dropped.
    dropStaleSelection(ui, client);
    // The participants of a clicked Event-log entry stay lit only while the time stays at it.
    dropStaleHighlight(ui);
    // The Time slider's zoom follows the time and stays inside the history.
    keepTimeWindow(ui, client);
  }

  /** Edits carry no `until`: the host computes ahead in slices (Calculation settings) after them. */
  private stamp<A extends Action>(a: A): A {
    return a;
  }

  /**
   * Adds a disc and selects it (a refused disc selects nothing). Added, it says which disc was added
   * where (a refusal is the engine's message, in the user's terms: doc/refusalTerms.ts).
   */
  async addBody(x: number, y: number, r: number, m = 1, v: Vec2 = [0, 0]): Promise<string | null> {
    const id = nextFreeId("b", this.client.latestFrame?.ids ?? [], this.doc.actions);
    const time = this.now();
    const err = await this.edit([this.stamp({ time, type: "addBody", id, x, y, r, m, mu: 0, v })]);
    if (err === null) {
      this.ui.setState({ selection: { kind: "body", id } });
      this.info(`Added disc "${id}" at ${point([x, y])}, radius ${shown(r)}${when(time)}.`);
    }
    return err;
  }

  /** Adds a line, ray or segment and selects it (a refused one selects nothing), and says so, as addBody. */
  async addLine(p1: Vec2, p2: Vec2, kind: "line" | "ray" | "segment"): Promise<string | null> {
    const id = nextFreeId("l", this.client.latestFrame?.lines.map((l) => l.id) ?? [], this.doc.actions);
    const time = this.now();
    const err = await this.edit([this.stamp({ time, type: "addLine", id, p1, p2, kind })]);
    if (err === null) {
      this.ui.setState({ selection: { kind: "line", id } });
      this.info(`Added ${kind} "${id}" from ${point(p1)} to ${point(p2)}${when(time)}.`);
    }
    return err;
  }

  /** Adds a fixed point and selects it (a refused one selects nothing), and says so, as addBody. */
  async addPoint(p: Vec2): Promise<string | null> {
    const id = nextFreeId("p", this.client.latestFrame?.points.map((q) => q.id) ?? [], this.doc.actions);
    const time = this.now();
    const err = await this.edit([this.stamp({ time, type: "addPoint", id, p })]);
    if (err === null) {
      this.ui.setState({ selection: { kind: "point", id } });
      this.info(`Added point "${id}" at ${point(p)}${when(time)}.`);
    }
    return err;
  }

  /**
   * Applies the edit of a field `action` (merged as edits are) and says what it set at what time and
   * what Undo restores (doc/editConfirm.ts: "Moved disc "b3" to (50, 0) at t = 2 s (Undo moves it
   * back to (40, 0))."): a move, a velocity drag, a cue strike, a table cell or a Globals button said
   * nothing, while adds and deletes did. The values before come from the frame at the edit's time,
   * asked for at its turn right before it is sent (after the changes queued before it).
   */
  private editSaid(action: FieldEdit, how?: "strike"): Promise<string | null> {
    const frame = (): Promise<Frame> =>
      this.client.hasFrame(action.time) && this.client.latestFrame !== null
        ? Promise.resolve(this.client.latestFrame)
        : this.client.frame(action.time);
    return this.edit([this.stamp(action)], true, async () =>
      confirmEdit(action, stateBefore(await frame(), action), how),
    );
  }

  moveBody(id: string, x: number, y: number): Promise<string | null> {
    return this.editSaid({ time: this.now(), type: "updateBody", id, x, y });
  }

  giveVelocity(id: string, v: Vec2, how?: "strike"): Promise<string | null> {
    return this.editSaid({ time: this.now(), type: "giveVelocity", id, v }, how);
  }

  /**
   * A cue strike: velocity away from the click point, STRIKE_RATE per unit of offset. With the
   * view's `scale` (a click of the pointer) it is rounded to what one pixel of the offset changes in
   * it (canvas/pointerPlace.ts strikeVelocity: never to [0, 0], which would stop the disc), not
   * given the digits of the pointer's position. A click at the centre itself gives no direction: it
   * is refused with a message and nothing changes.
   */
  strike(id: string, centre: Vec2, click: Vec2, scale?: number): Promise<string | null> {
    const dx = centre[0] - click[0];
    const dy = centre[1] - click[1];
    const v: Vec2 | null =
      scale === undefined
        ? dx === 0 && dy === 0
          ? null
          : [dx * STRIKE_RATE, dy * STRIKE_RATE]
        : strikeVelocity(dx, dy, STRIKE_RATE, scale);
    if (v === null) return Promise.resolve(this.fail(NO_STRIKE_DIRECTION));
    return this.giveVelocity(id, v, "strike");
  }

  updateBody(id: string, patch: { x?: number; y?: number; v?: Vec2; r?: number; m?: number; mu?: number }) {
    return this.editSaid({ time: this.now(), type: "updateBody", id, ...patch });
  }

  updateLine(id: string, patch: { p1?: Vec2; p2?: Vec2; kind?: "line" | "ray" | "segment" }) {
    return this.editSaid({ time: this.now(), type: "updateLine", id, ...patch });
  }

  updatePoint(id: string, p: Vec2) {
    return this.editSaid({ time: this.now(), type: "updatePoint", id, p });
  }

  setGlobal(patch: { g?: number; gravity?: Vec2 }) {
    return this.editSaid({ time: this.now(), type: "setGlobal", ...patch });
  }

  /**
   * Renames a body, line or point (EditorRewrites.rename), and says so and that Undo takes it back,
   * and which drafts of its other cells went with its row (its id cell's is the new name).
   */
  override async rename(kind: ObjectKind, from: string, to: string): Promise<string | null> {
    const dropped = this.drafts.of(kind, from, "id");
    const err = await super.rename(kind, from, to);
    if (err === null)
      this.info(
        withDropped(
          `Renamed ${kind} ${JSON.stringify(from)} to ${JSON.stringify(to)} (Undo takes it back).`,
          dropped,
        ),
      );
    return err;
  }

  /**
   * Removes the selected body, line or point at the current time, and says so (it said nothing), and
   * which drafts typed in its row went with it (they vanished without a word).
   */
  async deleteSelection(): Promise<string | null> {
    const sel = this.ui.getState().selection;
    if (!sel) return null;
    const dropped = this.drafts.of(sel.kind, sel.id);
    const type = sel.kind === "body" ? "removeBody" : sel.kind === "line" ? "removeLine" : "removePoint";
    const time = this.now();
    const err = await this.edit([this.stamp({ time, type, id: sel.id })]);
    if (err === null) {
      this.ui.setState({ selection: null });
      this.info(
        withDropped(
          `Deleted ${sel.kind} "${sel.id}" at t = ${shown(time)} s (Undo brings it back).`,
          dropped,
        ),
      );
    }
    return err;
  }

  /**
   * Removes `actions[index]` of the scene (an Event-log entry's actionIndex) as one undo step, the
   * current time and the history range kept. Refused when that index no longer holds the entry's
   * action (the scene changed since the log was read), and by the engine when a later action needs
   * it (its message says which one). Removed, it says which action went and that Undo brings it back,
   * and, for an add, which drafts typed in the row of the object it made went with it.
   */
  async removeAction(index: number, entry: ActionEntry): Promise<string | null> {
    const kind = ADDED_KIND[entry.type];
    const dropped = kind === undefined || entry.id === null ? [] : this.drafts.of(kind, entry.id);
    const err = await this.rewrite((doc) => withoutAction(doc, index, entry));
    if (err !== null) return err;
    const what = describeEntry(entry.type, entry.id);
    this.info(
      withDropped(
        `Removed ${what} at t = ${shown(entry.time)} s from the scene (Undo brings it back).`,
        dropped,
      ),
    );
    return null;
  }

  /**
   * Replaces `actions[index]` (checked to be `entry`'s, as removeAction checks it) by `next`, as one
   * undo step: the refused action's fields changed where the Event log lists it
   * (panels/RefusedActionRow.tsx). `field` names what changed, for the message.
   */
  async changeAction(index: number, entry: ActionEntry, next: Action, field: string): Promise<string | null> {
    const err = await this.rewrite((doc) => withActionChanged(doc, index, entry, next));
    if (err !== null) return err;
    const name = actionName(next) ?? `the action at t = ${shown(next.time)} s`;
    this.info(`Changed ${field} of ${name} (Undo brings back the action as it was).`);
    return null;
  }

  /**
   * Sets the scene's title (`meta.title`; blank: none; doc/sceneTitle.ts) as one undo step; nothing
   * is recomputed. A title names the file Save suggests unless the author chose its name (a file
   * opened, a name saved under: saving back to it stays the suggestion); the message says which
   * name Save file suggests. The same title again changes nothing (no undo step).
   */
  async setTitle(typed: string): Promise<string | null> {
    if (JSON.stringify(metaWithTitle(this.doc.meta, typed)) === JSON.stringify(this.doc.meta)) return null;
    let chosen = true;
    const err = await this.changeMeta(
      (doc) => metaWithTitle(doc.meta, typed),
      () => {
        chosen = this.names.chosen;
        // the titled scene starts a file of its own: Undo goes back to the preset's name
        if (!chosen) this.names.loaded(null);
      },
    );
    if (err !== null) return err;
    const title = titleOf(this.doc);
    const name = saveNameFor(this.names.name, this.doc);
    const said = title === "" ? "Removed the scene's title" : `Titled the scene ${JSON.stringify(title)}`;
    this.info(
      `${said}: Save file suggests ${name}${chosen ? " (the scene's own file)" : ""}. Undo takes it back.`,
    );
    return null;
  }

  /** Empties the scene (its gravity kept) as one undo step, and says that Undo brings it back. */
  async clear(): Promise<string | null> {
    const err = await this.loadScene(
      { ...EMPTY_SCENE, g: this.doc.g, gravity: this.doc.gravity },
      { reproducible: true },
    );
    if (err === null) this.info("Cleared the scene. Undo brings it back.");
    return err;
  }
}
