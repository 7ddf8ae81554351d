import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { EMPTY_HISTORY, HISTORY_LIMIT, record, redo, takenBack, undo } from "./history";

const scene = (n: number): SceneFile => ({
  format: "chapgame",
  version: 1,
  g: n,
  gravity: [0, 0],
  actions: [],
});

describe("history", () => {
  it("undo returns the scene before the last edit and redo returns to the edit", () => {
    const h = record(EMPTY_HISTORY, scene(1));
    const u = undo(h, scene(2));
    expect(u?.scene.g).toBe(1);
    const r = redo(u!.history, scene(1));
    expect(r?.scene.g).toBe(2);
    expect(r?.history.past.map((s) => s.g)).toEqual([1]);
  });

  it("nothing to undo or redo gives null", () => {
    expect(undo(EMPTY_HISTORY, scene(1))).toBeNull();
    expect(redo(EMPTY_HISTORY, scene(1))).toBeNull();
  });

  it("a new edit after undo clears the redo list", () => {
    const u = undo(record(EMPTY_HISTORY, scene(1)), scene(2))!;
    const h = record(u.history, scene(1));
    expect(h.future).toEqual([]);
    expect(h.past.map((s) => s.g)).toEqual([1]);
  });

  it("an edit taken back before it was recorded clears the redo list, the past stays", () => {
    const u = undo(record(record(EMPTY_HISTORY, scene(1)), scene(2)), scene(3))!;
    expect(u.history.future.map((s) => s.g)).toEqual([3]);
    const h = takenBack(u.history);
    expect(h.future).toEqual([]);
    expect(h.past).toBe(u.history.past);
    expect(takenBack(EMPTY_HISTORY)).toBe(EMPTY_HISTORY);
  });

  it("keeps at most HISTORY_LIMIT steps, dropping the oldest", () => {
    let h = EMPTY_HISTORY;
    for (let i = 0; i < HISTORY_LIMIT + 5; i++) h = record(h, scene(i));
    expect(h.past.length).toBe(HISTORY_LIMIT);
    expect(h.past[0]?.g).toBe(5);
  });
});
