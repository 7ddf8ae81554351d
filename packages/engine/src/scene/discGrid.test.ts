// DiscGrid's overlap query, and the review's hang: far from the origin (cell numbers beyond 2^53)
// the cell loop never advanced, so a scene with a disc at (4e16, 4e16) froze Timeline.fromScene.
import { describe, expect, it } from "vitest";
import { Timeline } from "../timeline/timeline.js";
import { DiscGrid } from "./discGrid.js";

describe("DiscGrid", () => {
  it("finds the smallest overlapping id, skips `except`, and nothing for a disc that only touches", () => {
    const g = new DiscGrid();
    g.insert("b", 0, 0, 1);
    g.insert("a", 1.5, 0, 1);
    g.insert("c", 10, 0, 1);
    expect(g.findOverlap(0.5, 0, 1, null)).toBe("a");
    expect(g.findOverlap(0.5, 0, 1, "a")).toBe("b");
    expect(g.findOverlap(12, 0, 1, null)).toBeNull();
  });

  it("answers far from the origin (cell numbers beyond 2^53) instead of looping", () => {
    for (const far of [4e16, 1e17, -1e17, 1e30]) {
      const g = new DiscGrid();
      g.insert("a", 0, 0, 1);
      g.insert("b", far, far, 1);
      expect(g.findOverlap(far, far + 1, 1, null)).toBe("b");
      expect(g.findOverlap(far, -far, 1, null)).toBeNull();
    }
  });

  it("a scene with a disc at (4e16, 4e16) loads (Timeline.fromScene returned only at 1e16 and below)", () => {
    const tl = Timeline.fromScene({
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, 0],
      actions: [
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
        { time: 0, type: "addBody", id: "b", x: 4e16, y: 4e16, r: 1, m: 1 },
      ],
    });
    expect(tl.stateAt(0).bodies.map((b) => b.id)).toEqual(["a", "b"]);
  });
});
