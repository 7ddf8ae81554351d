import { describe, expect, it } from "vitest";
import { droppedNote, OpenDrafts } from "./openDrafts";

const b3r = { label: "b3 r", text: "-1", owner: { kind: "body" as const, id: "b3", field: "r" } };
const b3id = { label: "b3 id", text: "ball", owner: { kind: "body" as const, id: "b3", field: "id" } };
const b4x = { label: "b4 x", text: "abc", owner: { kind: "body" as const, id: "b4", field: "x" } };
const g = { label: "g", text: "2", owner: null };

describe("OpenDrafts", () => {
  it("keeps one draft per cell, the last recorded, until the cell clears it", () => {
    const d = new OpenDrafts();
    d.set("c1", { ...b3r, text: "-" });
    d.set("c1", b3r);
    d.set("c2", g);
    expect(d.all()).toEqual([b3r, g]);
    d.set("c1", null);
    expect(d.all()).toEqual([g]);
  });

  it("gives an object's drafts, of its kind only, but the field left out", () => {
    const d = new OpenDrafts();
    d.set("a", b3r);
    d.set("b", b3id);
    d.set("c", b4x);
    d.set("d", g);
    expect(d.of("body", "b3")).toEqual([b3r, b3id]);
    expect(d.of("body", "b3", "id")).toEqual([b3r]);
    expect(d.of("line", "b3")).toEqual([]);
  });
});

describe("droppedNote", () => {
  it("says nothing when no draft was dropped", () => {
    expect(droppedNote([])).toBe("");
  });

  it("names each draft as typed, a number bare and other text quoted", () => {
    expect(droppedNote([b3r])).toBe("Dropped the draft b3 r = -1, typed and not applied.");
    expect(droppedNote([b3r, b4x])).toBe(
      'Dropped the drafts b3 r = -1 and b4 x = "abc", typed and not applied.',
    );
  });

  it("counts the drafts past the third", () => {
    expect(droppedNote([b3r, b4x, g, b3id, b3r])).toBe(
      'Dropped the drafts b3 r = -1, b4 x = "abc", g = 2 and 2 more, typed and not applied.',
    );
  });
});
