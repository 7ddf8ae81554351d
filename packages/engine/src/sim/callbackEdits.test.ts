/**
 * Edits made inside `advance`'s onEvent callback act as the same edits made between two advances
 * (the first stopped by maxEvents at that event): identical events, bit for bit. Before, an edit of
 * a line, a point or a global was ignored until the next advance (a disc passed through a line added
 * in the callback; a removed line crashed the loop), and advance called from its own callback broke
 * the World (audit, session 18).
 */
import { describe, expect, it } from "vitest";
import { ChapgameError } from "./errors.js";
import type { WorldEvent } from "./types.js";
import { World } from "./world.js";

/** A disc going up at speed 1 under a segment at y = 10 (first bounce at t = 9), with a floor and a peg below. */
function shaft(): World {
  const w = new World({ g: 0 });
  w.addLine("top", [-10, 10], [10, 10], "segment");
  w.addLine("floor", [-10, -5], [10, -5], "segment");
  w.addPoint("peg", [3, -20]);
  w.addBody("ball", { x: 0, y: 0, r: 1, m: 1, vy: 1 });
  w.addBody("other", { x: 3, y: 0, r: 1, m: 2, vy: -0.5 });
  return w;
}

type Edit = (w: World) => void;
const EDITS: [string, Edit][] = [
  ["addLine", (w) => w.addLine("mid", [-10, 5], [10, 5], "segment")],
  ["addPoint", (w) => w.addPoint("p", [0, 5])],
  ["updateLine", (w) => w.updateLine("floor", { p1: [-10, -15], p2: [10, -15] })],
  ["removeLine", (w) => w.removeLine("floor")],
  ["updatePoint", (w) => w.updatePoint("peg", [0, -12])],
  ["removePoint", (w) => w.removePoint("peg")],
  ["setGlobal gravity", (w) => w.setGlobal({ gravity: [0, -0.1] })],
  [
    "removeLine then updateBody",
    (w) => {
      w.removeLine("floor");
      w.updateBody("ball", { vx: 0.3 });
    },
  ],
];

const copy = (e: WorldEvent) => `${e.time}|${e.kind}|${e.a}|${e.b}|${e.px}|${e.py}|${e.impulse}`;

/** Events up to t = 60 with `edit` made in the callback of the first event. */
function editedInCallback(edit: Edit): string[] {
  const w = shaft();
  const out: string[] = [];
  let done = false;
  w.advance({ untilTime: 60 }, (e) => {
    out.push(copy(e));
    if (!done) {
      done = true;
      edit(w);
    }
  });
  return [...out, JSON.stringify(w.bodies())];
}

/** The same, with the first advance stopped after one event and the edit made between advances. */
function editedBetween(edit: Edit): string[] {
  const w = shaft();
  const out: string[] = [];
  w.advance({ maxEvents: 1 }, (e) => out.push(copy(e)));
  edit(w);
  w.advance({ untilTime: 60 }, (e) => out.push(copy(e)));
  return [...out, JSON.stringify(w.bodies())];
}

describe("edits inside advance's callback", () => {
  for (const [name, edit] of EDITS)
    it(`${name}: the same events, bit for bit, as the edit made between two advances`, () => {
      const between = editedBetween(edit);
      expect(between.length).toBeGreaterThan(3);
      expect(editedInCallback(edit)).toEqual(between);
    });

  it("a line added in the callback stops the disc (it passed through before)", () => {
    const w = shaft();
    let done = false;
    const hits: string[] = [];
    w.advance({ untilTime: 30 }, (e) => {
      hits.push(`${e.kind}:${e.b}`);
      if (!done) {
        done = true;
        w.addLine("mid", [-10, 5], [10, 5], "segment");
      }
    });
    expect(hits).toContain("bodyLine:mid");
    expect(w.body("ball").y).toBeGreaterThanOrEqual(6);
  });

  it("advance called from its own callback is refused, and the World goes on unharmed", () => {
    const w = shaft();
    const twin = shaft();
    let refused: unknown = null;
    w.advance({ maxEvents: 1 }, () => {
      try {
        w.advance({ untilTime: 20 });
      } catch (e) {
        refused = e;
      }
    });
    expect(refused).toBeInstanceOf(ChapgameError);
    expect((refused as ChapgameError).path).toBe("advance");
    twin.advance({ maxEvents: 1 });
    w.advance({ untilTime: 40 });
    twin.advance({ untilTime: 40 });
    expect(w.bodies()).toEqual(twin.bodies());
  });

  it("a callback that throws leaves advance usable again", () => {
    const w = shaft();
    expect(() =>
      w.advance({ untilTime: 20 }, () => {
        throw new Error("game bug");
      }),
    ).toThrow("game bug");
    expect(() => w.advance({ untilTime: 30 })).not.toThrow();
  });
});
