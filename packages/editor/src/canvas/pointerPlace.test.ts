// What the canvas's tools produce from the pointer: round places that the frame shown accepts (the
// moved disc left out of its own check), and velocities rounded to what a pixel of drag changes.
import { describe, expect, it } from "vitest";
import type { LineState } from "../engineTypes";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import { blockerAt, lineBlocker } from "./freeSpot";
import { placeLine, placeShape, pointerVelocity, strikeVelocity } from "./pointerPlace";

function frame(discs: [string, number, number, number][], lines: LineState[] = []): Frame {
  const data = new Float64Array(discs.length * FRAME_STRIDE);
  discs.forEach(([, x, y, r], i) => {
    data[i * FRAME_STRIDE + F_X] = x;
    data[i * FRAME_STRIDE + F_Y] = y;
    data[i * FRAME_STRIDE + F_R] = r;
  });
  return { t: 0, revision: 0, g: 0, gravity: [0, 0], ids: discs.map((d) => d[0]), data, lines, points: [] };
}

describe("placeShape", () => {
  it("rounds to the coarsest power of ten no larger than a pixel (no frame: rounded only)", () => {
    expect(placeShape(null, { kind: "point" }, [123.45678901234, -0.0123456], 10)).toEqual([123.5, 0]);
    expect(placeShape(null, { kind: "point" }, [123.45678901234, -0.0123456], 300)).toEqual([
      123.457, -0.012,
    ]);
    expect(placeShape(null, { kind: "disc", r: 1 }, [123.45678901234, 7.77], 0.05)).toEqual([120, 10]);
  });

  it("a disc next to a wall is never rounded into it: the nearest round place clear of it", () => {
    const wall: LineState = { id: "w", p1: [10, -5], p2: [10, 5], kind: "line" };
    const f = frame([], [wall]);
    // aimed 0.01 clear of the wall: 8.96 rounds to 9.0, 0.03 into it
    const c = placeShape(f, { kind: "disc", r: 1.03 }, [8.96, 2.02], 10);
    expect(c).toEqual([8.9, 2]);
    expect(blockerAt(f, { kind: "disc", r: 1.03 }, c, 0)).toBeNull();
    expect(blockerAt(f, { kind: "disc", r: 1.03 }, [9, 2], 0)).toEqual({ kind: "line", id: "w" });
  });

  it("a moved disc is not in its own way; the others are", () => {
    // d0 moved towards d1 (contact at 2): aimed 2.03 from it, rounded 1.99
    const f = frame([
      ["d0", 0, 0, 1],
      ["d1", 2.69, 0, 1],
    ]);
    expect(placeShape(f, { kind: "disc", r: 1 }, [0.66, 0], 10, "d0")).toEqual([0.6, 0]);
    // counted in its own way, the aim itself is refused, and the rounded place is given as it is
    expect(placeShape(f, { kind: "disc", r: 1 }, [0.66, 0], 10)).toEqual([0.7, 0]);
  });
});

describe("a rounded place is never across something from the aim (review of session 23)", () => {
  // A disc or a line smaller than a pixel could be rounded to the far side of a wall or of a disc:
  // clear there too, but a disc aimed inside a box then starts outside it.
  it("a disc smaller than a pixel next to a wall stays on the aim's side", () => {
    const wall: LineState = { id: "w", p1: [0.04, -5], p2: [0.04, 5], kind: "line" };
    const f = frame([], [wall]);
    // aimed 0.005 right of the wall (radius 0.001): rounded to x = 0, clear of it but left of it
    const c = placeShape(f, { kind: "disc", r: 0.001 }, [0.045, 0.02], 10);
    expect(c[0]).toBeGreaterThan(0.04);
    expect(c).toEqual([0.1, 0]);
    // a moved one likewise, and a point placed next to a segment
    const seg: LineState = { id: "s", p1: [0.04, -5], p2: [0.04, 5], kind: "segment" };
    expect(
      placeShape(frame([["d", 3, 3, 0.001]], [seg]), { kind: "disc", r: 0.001 }, [0.045, 0], 10, "d"),
    ).toEqual([0.1, 0]);
    expect(placeShape(frame([], [seg]), { kind: "point" }, [0.045, 0], 10)[0]).toBeGreaterThan(0.04);
  });

  it("a disc smaller than a pixel is not rounded through another one", () => {
    // b at x = 0.03 (radius 0.001); aimed right of it at 0.04, rounding to 0 would pass through it
    const f = frame([["b", 0.03, 0, 0.001]]);
    expect(placeShape(f, { kind: "disc", r: 0.001 }, [0.04, 0], 10)).toEqual([0.1, 0]);
  });

  it("a line drawn next to a disc smaller than a pixel keeps the disc on the same side", () => {
    const f = frame([["d", 0, 0.03, 0.01]]);
    // drawn 0.015 above the disc's centre: rounded to y = 0 it would pass below it
    for (const kind of ["segment", "ray", "line"] as const) {
      const [p1, p2] = placeLine(f, [-5.01, 0.045], [5.02, 0.045], kind, 10);
      // up on both axes strays least of the corners that keep it above (as in the test above)
      expect([p1, p2], kind).toEqual([
        [-5, 0.1],
        [5.1, 0.1],
      ]);
    }
    // a segment that ends well before the disc is rounded as it is
    expect(placeLine(f, [1.01, 0.045], [5.02, 0.045], "segment", 10)).toEqual([
      [1, 0],
      [5, 0],
    ]);
  });
});

describe("placeLine", () => {
  it("rounds both ends, and moves a line rounding would take into a disc clear of it, level", () => {
    expect(placeLine(null, [1.2345, 6.789], [-3.21, 0.049], "ray", 10)).toEqual([
      [1.2, 6.8],
      [-3.2, 0],
    ]);
    const f = frame([["d0", 0, 0, 1.02]]);
    const [p1, p2] = placeLine(f, [-5.01, 1.04], [5.04, 1.04], "segment", 10);
    expect([p1, p2]).toEqual([
      [-5, 1.1],
      [5.1, 1.1],
    ]);
    expect(lineBlocker(f, [-5, 1], [5, 1], "segment")).toEqual({ kind: "body", id: "d0" });
    expect(lineBlocker(f, p1, p2, "segment")).toBeNull();
    // a ray pointing away from the disc does not reach it; the line through the same points does
    expect(lineBlocker(f, [3, 0], [4, 0], "ray")).toBeNull();
    expect(lineBlocker(f, [3, 0], [4, 0], "line")).toEqual({ kind: "body", id: "d0" });
  });
});

describe("pointerVelocity", () => {
  it("rounds each component to what one pixel of the drag changes in it", () => {
    // a drag at 10 px per unit, 2 per unit (the arrow's half second): a pixel is 0.2, step 0.1
    expect(pointerVelocity(1.234, 5.678, 2, 10)).toEqual([2.5, 11.4]);
    // a cue (4 per unit) at 500 px per unit: a pixel is 0.008, step 0.001
    expect(pointerVelocity(-0.33712345, 0.2131, 4, 500)).toEqual([-1.348, 0.852]);
  });
});

describe("strikeVelocity", () => {
  it("is pointerVelocity's rounding while that leaves a component other than 0", () => {
    expect(strikeVelocity(-0.33712345, 0.2131, 4, 500)).toEqual(pointerVelocity(-0.33712345, 0.2131, 4, 500));
    expect(strikeVelocity(0.02, 0, 4, 10)).toEqual([0.1, 0]); // 0.08 rounds to 0.1
  });

  it("a click that rounds to [0, 0] gives one step along its larger component, the other rounded to the step", () => {
    // 4 per unit at 10 px per unit: a pixel is 0.4, step 0.1
    expect(pointerVelocity(-0.01, 0.004, 4, 10)).toEqual([0, 0]);
    expect(strikeVelocity(-0.01, 0.004, 4, 10)).toEqual([-0.1, 0]);
    expect(strikeVelocity(0.009, -0.008, 4, 10)).toEqual([0.1, -0.1]);
    expect(strikeVelocity(0, 1e-9, 4, 10)).toEqual([0, 0.1]);
    // at 500 px per unit: a pixel is 0.008, step 0.001
    expect(strikeVelocity(-1e-5, -1.5e-5, 4, 500)).toEqual([-0.001, -0.001]);
  });

  it("a click at the centre itself gives no direction: null", () => {
    expect(strikeVelocity(0, 0, 4, 10)).toBeNull();
  });
});
