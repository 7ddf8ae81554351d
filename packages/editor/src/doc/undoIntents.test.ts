import { describe, expect, it } from "vitest";
import {
  canRedo,
  canUndo,
  changeAsked,
  isUndone,
  NO_INTENTS,
  redoAsked,
  redoTurn,
  type Ticket,
  undoAsked,
  undoTurn,
} from "./undoIntents";

const ticket = (): Ticket => ({ fate: "queued" });

describe("undoIntents", () => {
  it("an Undo asked while a change is queued is bound to that change, the next one to the recorded past", () => {
    const t = ticket();
    const s = changeAsked(NO_INTENTS, t);
    const u1 = undoAsked(s);
    expect(u1.ticket).toBe(t);
    expect(isUndone(u1.intents, t)).toBe(true);
    const u2 = undoAsked(u1.intents);
    expect(u2.ticket).not.toBe(t);
    expect(u2.ticket.fate).toBe("done"); // stands for the recorded past's last entry
    expect(u2.intents.future).toEqual([u2.ticket, t]);
  });

  it("Redo is bound to the last ticket Undo took, and a change asked clears Redo", () => {
    const t = ticket();
    const u = undoAsked(changeAsked(NO_INTENTS, t));
    const r = redoAsked(u.intents);
    expect(r.ticket).toBe(t);
    expect(isUndone(r.intents, t)).toBe(false);
    // a change asked since: the recorded future will be cleared, Redo has nothing
    expect(redoAsked(r.intents).ticket).toBeNull();
    expect(canRedo(r.intents, 3)).toBe(false);
    // without changes asked, Redo is bound to the recorded future's first entry
    const plain = redoAsked(NO_INTENTS);
    expect(plain.ticket?.fate).toBe("done");
    expect(canRedo(NO_INTENTS, 1)).toBe(true);
  });

  it("at its turn an Undo undoes a change that is there, records one taken back, skips one refused", () => {
    expect(undoTurn({ fate: "done" })).toBe("undo");
    expect(undoTurn({ fate: "takenBack" })).toBe("toFuture");
    expect(undoTurn({ fate: "refused" })).toBe("nothing");
    expect(redoTurn({ fate: "done" })).toBe("redo");
    expect(redoTurn({ fate: "refused" })).toBe("nothing");
    expect(redoTurn(null)).toBe("nothing");
  });

  it("Undo is offered while a change is in flight, even with nothing recorded yet", () => {
    expect(canUndo(NO_INTENTS, 0)).toBe(false);
    expect(canUndo(changeAsked(NO_INTENTS, ticket()), 0)).toBe(true);
  });
});
