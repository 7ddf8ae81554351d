/**
 * SceneChanges: the queue of an EditorSession's scene changes (loads, edits, undo, redo, renames)
 * and the Undo intents over them. Changes run strictly one after another (serial): each reads the
 * scene and the history its predecessors left; only the change itself is queued, not the computing
 * ahead that follows it. Each undoable change gets a ticket when asked (ticketed;
 * doc/undoIntents.ts), so an Undo asked while it is still queued or checked is bound to it. An Undo
 * bound to a running change whose later actions the host is still checking asks the host to take
 * it back (takeBackIfUndone: client.takeBack, the change goes, nothing else), and the refusal that
 * follows is then known as that take-back (tookBack). Only the last change asked is taken back so:
 * a change queued behind a running one was asked on a scene holding it (taken back, the later change
 * ran without it and its Redo entry lost it), so an Undo bound to the running one waits for its turn
 * (after the later changes' own Undos) and undoes it then. Intents are cleared once no change is queued.
 */

import { changeAsked, type Intents, isUndone, NO_INTENTS, type Ticket } from "./doc/undoIntents";
import type { SceneFile } from "./engineTypes";
import type { TimelineClient } from "./remote/client";
import { createStore, type Store } from "./store/createStore";

export class SceneChanges {
  /** Undo and Redo as the user asked them, over the history, while changes are queued (undoIntents.ts). */
  readonly intents: Store<Intents> = createStore<Intents>(NO_INTENTS);
  /** Scene changes queued or running (intents are cleared when none is left). */
  private queued = 0;
  /** The take-back asked for a running change an Undo is bound to (client.takeBack). */
  private readonly takeBacks = new WeakMap<Ticket, Promise<SceneFile | null>>();
  /** The tickets of the undoable changes queued or running, in the order asked. */
  private readonly asked: Ticket[] = [];
  /** The tail of the queue of scene changes (see serial). */
  private changes: Promise<unknown> = Promise.resolve();

  constructor(private readonly client: Pick<TimelineClient, "takeBack">) {}

  /**
   * Runs `change` once every scene change queued before it has been applied and recorded, so each
   * one reads the scene and the history its predecessors left. Only the change itself is queued:
   * the computing ahead that follows it is not waited for.
   */
  serial<T>(change: () => Promise<T>): Promise<T> {
    this.queued++;
    const run = this.changes.then(change).finally(() => {
      // Nothing queued: the history recorded is the history the user asked for.
      if (--this.queued === 0) this.intents.setState(NO_INTENTS);
    });
    this.changes = run.catch(() => undefined);
    return run;
  }

  /**
   * `change` (an undoable change: it resolves to null or the message, after recording its undo
   * step) queued with a ticket taken now, which says what became of it (undoIntents.ts).
   */
  ticketed(change: (ticket: Ticket) => Promise<string | null>): Promise<string | null> {
    const ticket: Ticket = { fate: "queued" };
    this.intents.setState(changeAsked(this.intents.getState(), ticket));
    this.asked.push(ticket);
    return this.serial(async () => {
      ticket.fate = "running";
      try {
        const err = await change(ticket);
        if (ticket.fate === "running") ticket.fate = err === null ? "done" : "refused";
        return err;
      } finally {
        this.takeBacks.delete(ticket);
        this.asked.splice(this.asked.indexOf(ticket), 1);
      }
    });
  }

  /**
   * Asks the host to take back the running change of `ticket` if an Undo is bound to it and its
   * later actions are being checked (an Undo during the check: the change goes, nothing else), and
   * no change was asked after it (see the header: that Undo then undoes it at its turn).
   */
  takeBackIfUndone(ticket: Ticket): void {
    if (ticket.fate !== "running" || this.takeBacks.has(ticket)) return;
    if (this.asked.at(-1) !== ticket || !isUndone(this.intents.getState(), ticket)) return;
    this.takeBacks.set(
      ticket,
      this.client.takeBack().catch(() => null),
    );
  }

  /** After the change of `ticket` was refused: whether an Undo took it back (its fate is then set). */
  async tookBack(ticket: Ticket): Promise<boolean> {
    const scene = await (this.takeBacks.get(ticket) ?? null);
    if (scene === null) return false;
    ticket.fate = "takenBack";
    ticket.scene = scene;
    return true;
  }
}
