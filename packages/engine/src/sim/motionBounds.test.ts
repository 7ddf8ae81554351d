// A user's addBodyMotion is held to the range the contact polynomials can work in
// (MOTION_MAGNITUDE_MAX): speeds and positions beyond it are refused naming the field, where they
// were accepted and a disc at vx = 1e200 flew through the disc in its path without an event or an
// error (session 30's adversarial pass; addBody's bounds did not apply to restored motions). Motions
// beyond the edit bounds (MAGNITUDE_MAX) but within it, as a World under gravity 1e30 reaches, are
// still accepted, and a disc at such a speed still hits what is in its path.
import { describe, expect, it } from "vitest";
import { MAGNITUDE_MAX, MOTION_MAGNITUDE_MAX } from "../tolerances.js";
import { refusal } from "./testSupport.js";
import { World } from "./world.js";

/** A disc restored at the origin moving along +x at `vx`, a resting disc at x = 10, a line at x = 20. */
function flight(vx: number): World {
  const w = new World({ g: 0 });
  w.addBodyMotion("a", { t0: 0, x0: 0, y0: 0, vx, vy: 0, r: 1, m: 1, mu: 0 });
  w.addBody("b", { x: 10, y: 0, r: 1, m: 1 });
  w.addLine("L", [20, 0], [20, 1], "line");
  return w;
}

describe("addBodyMotion's magnitudes", () => {
  it("a restored disc faster than the edit bounds hits the disc in its path at every speed it accepts", () => {
    for (const vx of [2 * MAGNITUDE_MAX, 1e50, MOTION_MAGNITUDE_MAX]) {
      const w = flight(vx);
      const hits: [string | null, number][] = [];
      w.advance({ maxEvents: 1 }, (e) => hits.push([e.b, e.time * vx]));
      expect(hits.length).toBe(1);
      expect(hits[0]?.[0]).toBe("b");
      expect(Math.abs((hits[0]?.[1] as number) - 8)).toBeLessThan(1e-12);
    }
  });

  it("refuses a speed beyond MOTION_MAGNITUDE_MAX, naming the field and the value (it flew through at 1e200)", () => {
    const w = new World({ g: 0 });
    const e = refusal(() => w.addBodyMotion("a", { t0: 0, x0: 0, y0: 0, vx: 1e200, vy: 0, r: 1, m: 1 }));
    expect(e.path).toBe("vx");
    expect(e.reason).toBe(
      `must be at most ${MOTION_MAGNITUDE_MAX} in size (got 1e+200): the contact polynomials overflow beyond it`,
    );
    expect(
      refusal(() => w.addBodyMotion("a", { t0: 0, x0: 0, y0: 0, vx: 0, vy: -1e155, r: 1, m: 1 })).path,
    ).toBe("vy");
    expect(
      refusal(() => w.addBodyMotion("a", { t0: 0, x0: 1e100, y0: 0, vx: 0, vy: 0, r: 1, m: 1 })).path,
    ).toBe("x0");
    expect(w.bodies()).toEqual([]);
  });

  it("refuses a motion that puts the body beyond it now, naming the position (t0 = -1e300 put it at 1e254)", () => {
    const w = new World({ g: 0 });
    const e = refusal(() => w.addBodyMotion("a", { t0: -1e300, x0: 0, y0: 0, vx: 1e-30, vy: 0, r: 1, m: 1 }));
    expect(e.path).toBe("x0");
    expect(e.reason).toMatch(
      /^the motion puts the body at x = 1\.\d+e\+2\d\d at the world's time 0, beyond 1e\+70 in size: the contact polynomials overflow there$/,
    );
    const up = refusal(() => w.addBodyMotion("a", { t0: -1e60, x0: 0, y0: 0, vx: 0, vy: 1e20, r: 1, m: 1 }));
    expect(up.path).toBe("y0");
    expect(w.bodies()).toEqual([]);
    // a motion that started long ago is fine while it stays in range
    w.addBodyMotion("a", { t0: -1e40, x0: 0, y0: 0, vx: 1e-30, vy: 0, r: 1, m: 1 });
    expect(w.body("a").x).toBe(1e40 * 1e-30); // 1e10, rounded
  });
});

describe("a motion that overflows by the world's time", () => {
  it("is refused naming t0 and the place it reaches (it said 'y0: must be a finite number (got -Infinity)' for a y0 of 0)", () => {
    const w = new World({ g: 0, gravity: [0, -1e30] });
    const e = refusal(() => w.addBodyMotion("a", { t0: -1e300, x0: 0, y0: 0, vx: 0, vy: 0, r: 1, m: 1 }));
    expect(e.path).toBe("t0");
    expect(e.reason).toBe(
      "the motion from t0 = -1e+300 puts the body at y = -Infinity at the world's time 0, beyond the range of doubles (got -1e+300): give a t0 nearer the world's time",
    );
    expect(w.bodyCount).toBe(0);
  });
});
