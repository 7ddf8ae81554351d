import { describe, expect, it } from "vitest";
import { Timeline } from "../timeline/timeline.js";
import {
  FIELD_MIN,
  MAGNITUDE_MAX,
  MASS_MAX,
  MASS_MIN,
  RADIUS_MIN,
  SPEED_MIN,
  TIME_MAX,
} from "../tolerances.js";
import { SceneError } from "./errors.js";
import { parseScene } from "./parse.js";
import { serializeScene } from "./serialize.js";
import type { SceneFile } from "./types.js";

const scene = (actions: unknown[], extra: Record<string, unknown> = {}) =>
  ({ format: "chapgame", version: 1, g: 0, gravity: [0, 0], ...extra, actions }) as unknown as SceneFile;
const disc = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 };

function refusal(run: () => unknown): string {
  try {
    run();
  } catch (e) {
    expect(e).toBeInstanceOf(SceneError);
    return (e as Error).message;
  }
  throw new Error("accepted");
}

describe("scene magnitudes: parseScene refuses what the Timeline would, naming the scene's field", () => {
  // Before (review 7), parseScene and serializeScene accepted these and fromScene refused them,
  // some as a ChapgameError, and velocities under the World's names (actions[0].vx).
  const cases: [string, SceneFile, string][] = [
    [
      "a speed below SPEED_MIN",
      scene([{ ...disc, v: [1e-300, 0] }]),
      "actions[0].v[0]: must be 0 or at least",
    ],
    ["a position beyond MAGNITUDE_MAX", scene([{ ...disc, x: 1e31 }]), "actions[0].x: must be at most"],
    ["a radius below RADIUS_MIN", scene([{ ...disc, r: 1e-31 }]), "actions[0].r: must be between"],
    [
      "a tiny friction coefficient",
      scene([{ ...disc, mu: 1e-31 }], { g: 1 }),
      "actions[0].mu: must be 0 or at least",
    ],
    ["a tiny friction field", scene([disc], { g: 1e-31 }), "g: must be 0 or at least"],
    [
      "a tiny gravity component",
      scene([disc], { gravity: [0, -1e-31] }),
      "gravity[1]: must be 0 or at least",
    ],
    [
      "a far line end",
      scene([{ time: 0, type: "addLine", id: "l", p1: [1e31, 0], p2: [0, 5], kind: "line" }]),
      "actions[0].p1[0]: must be at most",
    ],
    [
      "a far point",
      scene([{ time: 0, type: "addPoint", id: "p", p: [0, 2e30] }]),
      "actions[0].p[1]: must be at most",
    ],
    [
      "setGlobal with a tiny g",
      scene([disc, { time: 1, type: "setGlobal", g: 1e-35 }]),
      "actions[1].g: must be 0 or at least",
    ],
    [
      "giveVelocity beyond MAGNITUDE_MAX",
      scene([disc, { time: 1, type: "giveVelocity", id: "a", v: [0, 1e31] }]),
      "actions[1].v[1]: must be at most",
    ],
    [
      "updateBody with a tiny speed",
      scene([disc, { time: 1, type: "updateBody", id: "a", v: [0, -1e-31] }]),
      "actions[1].v[1]: must be 0 or at least",
    ],
    [
      "an action time beyond TIME_MAX (audit of session 19: x came out 1e300)",
      scene([disc, { time: 1e300, type: "giveVelocity", id: "a", v: [1, 0] }]),
      "actions[1].time: must be at most 1e+30 in size",
    ],
    [
      "a mass below MASS_MIN (5e-324 was accepted)",
      scene([{ ...disc, m: 5e-324 }]),
      "actions[0].m: must be between",
    ],
    [
      "a mass beyond MASS_MAX in updateBody (1e308 was accepted)",
      scene([disc, { time: 1, type: "updateBody", id: "a", m: 1e308 }]),
      "actions[1].m: must be between 1e-40 and 1e+40, or Infinity",
    ],
    [
      "until.events beyond Number.MAX_SAFE_INTEGER (1e20 was accepted; the CLI's --max-events refuses it)",
      scene([{ ...disc, until: { events: 1e20 } }]),
      "actions[0].until.events: must be a non-negative integer at most 9007199254740991",
    ],
  ];
  for (const [name, s, message] of cases)
    it(name, () => {
      const parsed = refusal(() => parseScene(s));
      expect(parsed.startsWith(message)).toBe(true);
      expect(refusal(() => Timeline.fromScene(s))).toBe(parsed);
      expect(refusal(() => serializeScene(s))).toBe(parsed);
    });

  it("accepts the bounds themselves, as the Timeline does", () => {
    const s = scene(
      [
        {
          ...disc,
          x: MAGNITUDE_MAX,
          r: RADIUS_MIN,
          mu: FIELD_MIN,
          v: [SPEED_MIN, -MAGNITUDE_MAX],
          m: MASS_MIN,
        },
        { time: 0, type: "addPoint", id: "p", p: [-MAGNITUDE_MAX, 0] },
        { time: 0, type: "addBody", id: "b", x: 10, y: 10, r: 1, m: MASS_MAX },
        { time: 0, type: "addBody", id: "c", x: 20, y: 10, r: 1, m: Number.POSITIVE_INFINITY },
        { time: TIME_MAX, type: "removeBody", id: "c", until: { events: Number.MAX_SAFE_INTEGER } },
      ],
      { g: FIELD_MIN },
    );
    expect(parseScene(s).actions).toHaveLength(5);
    expect(Timeline.fromScene(s, { compute: false }).actions).toHaveLength(5);
  });

  it("the Timeline's own g and gravity options are refused as a SceneError too", () => {
    expect(refusal(() => new Timeline({ g: 1e-40 }))).toMatch(/^g: must be 0 or at least/);
    expect(refusal(() => new Timeline({ gravity: [2e30, 0] }))).toMatch(/^gravity\[0\]: must be at most/);
  });
});
