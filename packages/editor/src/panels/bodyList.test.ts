import { describe, expect, it } from "vitest";
import { listBodies, listNote } from "./bodyList";

const ids = Array.from({ length: 200 }, (_, i) => `ball${i + 1}`).sort(); // frames list ids in string order
const listedIds = (filter: string, selected: string | null, max = 60) =>
  listBodies(ids, filter, selected, max).listed.map((i) => ids[i]);

describe("listBodies", () => {
  it("without a filter: the first `max` in natural order, and the selected body", () => {
    const shown = listedIds("", "ball150");
    expect(shown.slice(0, 3)).toEqual(["ball1", "ball2", "ball3"]);
    expect(shown).toHaveLength(61);
    expect(shown.at(-1)).toBe("ball150");
  });

  it("a filter reaches any body, case-insensitively, by a part of its id", () => {
    expect(listedIds("BALL199", null)).toEqual(["ball199"]);
    expect(listedIds("15", null)).toEqual([
      "ball15",
      "ball115",
      "ball150",
      "ball151",
      "ball152",
      "ball153",
      "ball154",
      "ball155",
      "ball156",
      "ball157",
      "ball158",
      "ball159",
    ]);
  });

  it("the selected body stays listed when it does not match", () => {
    expect(listedIds("ball199", "ball3")).toEqual(["ball3", "ball199"]);
  });

  it("the bodies holding an open cell stay listed, past `max` and whatever the filter", () => {
    const kept = new Set(["ball150", "ball7"]);
    const listed = (filter: string) => listBodies(ids, filter, null, 60, kept).listed.map((i) => ids[i]);
    expect(listed("")).toHaveLength(61);
    expect(listed("").at(-1)).toBe("ball150");
    expect(listed("ball199")).toEqual(["ball7", "ball150", "ball199"]);
    expect(listBodies(ids, "ball199", null, 60, kept).shown, "not counted as matches").toBe(1);
  });
});

describe("listNote", () => {
  it("says how many are left out and how to find them", () => {
    expect(listNote(listBodies(ids, "", null, 60), 200, "")).toBe(
      "Showing 60 of 200 bodies: filter by id to find the others.",
    );
    expect(listNote(listBodies(ids, "1", null, 60), 200, "1")).toBe('Showing 60 of 119 bodies matching "1".');
    expect(listNote(listBodies(ids, "zz", null, 60), 200, "zz")).toBe('No body id contains "zz".');
    expect(listNote(listBodies(ids, "ball199", null, 60), 200, "ball199")).toBeNull();
    expect(listNote(listBodies(ids.slice(0, 5), "", null, 60), 5, "")).toBeNull();
  });
});
