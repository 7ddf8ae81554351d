import { describe, expect, it } from "vitest";
import { parseScene } from "../scene/parse.js";
import { Timeline } from "../timeline/timeline.js";
import { OVERLAP_REL } from "../tolerances.js";
import { World } from "./world.js";

/**
 * Touching, as the World's placement checks see it, is the scene file's touching: an overlap of up
 * to OVERLAP_REL of the contact distance. Audit of session 15: two discs sqrt(3) apart in y and 1
 * in x (r = 1, so touching; the squared distance rounds to 3.9999999999999996) passed parseScene
 * and were then refused by the World when the CLI ran the scene.
 */
describe("touching with round-off is allowed at every edit", () => {
  const s3 = Math.sqrt(3);

  it("a disc touching another only to the last digit is accepted by the World, the Timeline and the CLI's path", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1 });
    expect(() => w.addBody("b", { x: 1, y: s3, r: 1, m: 1 })).not.toThrow();
    expect(() => w.updateBody("b", { x: 1, y: s3 * (1 - OVERLAP_REL / 4) })).not.toThrow();
    const scene = parseScene(
      JSON.stringify({
        format: "chapgame",
        version: 1,
        g: 0,
        actions: [
          { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
          { time: 0, type: "addBody", id: "b", x: 1, y: s3, r: 1, m: 1, v: [-1, -s3] },
        ],
      }),
    );
    const tl = Timeline.fromScene(scene, { compute: false });
    expect(tl.prolong({ time: 1 }).events).toBe(1); // b approaches a: they collide at once
    expect(tl.event(tl.eventCount - 1)).toMatchObject({ type: "bodyBody", time: 0 });
  });

  it("an overlap beyond the slack is still refused, for discs, lines and points", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1 });
    expect(() => w.addBody("b", { x: 2 * (1 - 2 * OVERLAP_REL), y: 0, r: 1, m: 1 })).toThrow(
      'x: the body would overlap body "a"',
    );
    expect(() => w.addLine("l", [1 - 2 * OVERLAP_REL, -1], [1 - 2 * OVERLAP_REL, 1], "line")).toThrow(
      'the line would overlap body "a"',
    );
    expect(() => w.addPoint("p", [1 - 2 * OVERLAP_REL, 0])).toThrow('the point would lie inside body "a"');
  });

  it("a line or a point touching a disc to within round-off is accepted, and the disc bounces at once", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    const edge = 1 - OVERLAP_REL / 4;
    expect(() => w.addLine("l", [edge, -5], [edge, 5], "line")).not.toThrow();
    expect(() => w.addPoint("p", [0, -edge])).not.toThrow();
    const kinds: string[] = [];
    w.advance({ untilTime: 1 }, (e) => kinds.push(`${e.kind}@${e.time}`));
    expect(kinds).toEqual(["bodyLine@0"]);
    expect(w.body("a", 1).vx).toBe(-1);
  });
});
