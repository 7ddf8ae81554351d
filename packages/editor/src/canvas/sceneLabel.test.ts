import { describe, expect, it } from "vitest";
import { sceneLabel } from "./sceneLabel";

describe("sceneLabel", () => {
  it("names the counts of what the view shows, singular and plural", () => {
    expect(sceneLabel({ bodies: 1, lines: 4, points: 0 }, null)).toBe(
      "Scene view: 1 body, 4 lines, 0 points",
    );
  });
  it("names the selection", () => {
    expect(sceneLabel({ bodies: 2, lines: 0, points: 1 }, { kind: "body", id: "ball2" })).toBe(
      "Scene view: 2 bodies, 0 lines, 1 point; selected: body ball2",
    );
  });
  it("says when there is no frame yet", () => {
    expect(sceneLabel(null, null)).toBe("Scene view (loading)");
  });
});
