import { describe, expect, it } from "vitest";
import { FILTER_SCAN_LIMIT } from "../remote/eventQueries";
import { closeIds, editDistance, filterNote, sceneIds } from "./filterNote";

const ids = sceneIds([
  { time: 0, type: "addBody", id: "b1" },
  { time: 0, type: "addBody", id: "b3" },
  { time: 0, type: "addBody", id: "ball" },
  { time: 0, type: "addLine", id: "floor" },
  { time: 1, type: "setGlobal" },
]);

describe("filterNote", () => {
  it("says nothing without a filter, or when the filter keeps entries", () => {
    expect(filterNote("  ", 0, ids, 10, 5)).toBeNull();
    expect(filterNote("zz", 3, ids, 10, 5)).toBeNull();
  });

  it("says no object has the id, with the ids close to it", () => {
    expect(filterNote("b4", 0, ids, 10, 5)).toBe(
      'No body, line or point has the id "b4". Close: "b1", "b3".',
    );
    expect(filterNote("zz", 0, ids, 10, 5)).toBe('No body, line or point has the id "zz".');
    expect(filterNote("b1, zz, q", 0, ids, 10, 5)).toBe('No body, line or point has the ids "zz", "q".');
  });

  it("says an id of the scene takes part in no entry of the computed history, or none together", () => {
    expect(filterNote("floor", 0, ids, 10, 2.5)).toBe(
      '"floor" takes part in no entry of the computed history (up to t = 2.5 s).',
    );
    expect(filterNote("b1, b3", 0, ids, 10, 2.5)).toBe(
      '"b1", "b3" take part in no entry together of the computed history (up to t = 2.5 s).',
    );
    expect(filterNote("b1", 0, ids, 2 * FILTER_SCAN_LIMIT + 1, 9)).toBe(
      `"b1" takes part in no entry within ${FILTER_SCAN_LIMIT} entries either side of the current time.`,
    );
  });

  it("reads an id that holds a comma as that id, as the log's filter does", () => {
    const odd = sceneIds([{ id: "a, b" }]);
    expect(filterNote("a, b", 0, odd, 1, 1)).toBe(
      '"a, b" takes part in no entry of the computed history (up to t = 1 s).',
    );
  });
});

describe("closeIds and editDistance", () => {
  it("finds ids a few edits away (fewer than the shorter has characters) or holding the text, closest first", () => {
    expect(closeIds("BAL", ["ball", "b1", "wall"])).toEqual(["ball", "wall"]);
    expect(closeIds("b4", ["a", "c", "b3"])).toEqual(["b3"]);
    expect(closeIds("x", ["b10", "b2"])).toEqual([]);
    expect(closeIds("b", ["b10", "b2", "b1", "b3"])).toEqual(["b1", "b2", "b3"]);
  });

  it("counts single-character edits, capped past the limit", () => {
    expect(editDistance("kitten", "sitting", 5)).toBe(3);
    expect(editDistance("abc", "abc", 2)).toBe(0);
    expect(editDistance("a", "abcdef", 2)).toBe(3);
  });
});
