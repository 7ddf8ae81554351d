import { describe, expect, it } from "vitest";
import { Timeline } from "../timeline/timeline.js";
import { OVERLAP_REL } from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { World } from "./world.js";

/**
 * A disc placed touching a ramp, a line or a point under gravity rests there: the exact model
 * refuses it (a resting contact), whatever the slope. Audit of session 17: how the slope rounded
 * decided between that refusal (0°, 5°, 45°), a bounce at the rounding level that never ended
 * (2,000,000 events in 8e-8 s at 10°) and a fall through the ramp (20°, 30°: the disc, left a
 * rounding inside it and rising too little to get out, never met it again). Of 399 slopes, 70
 * fell through and 33 hung; off the origin (centre near (100, 50)), 170 and 5. Fixed by
 * CONTACT_BAND (physics/timeOfImpact.ts, physics/quarticCrossing.ts).
 */
const GRAVITY: [number, number] = [0, -9.81];
const SLOPES = Array.from({ length: 399 }, (_, i) => ((i + 1) * 90) / 400);

/** The outcome of 2 s of the world: "rest" (refused at t = 0 as resting), else what went wrong. */
function outcome(w: World): string {
  try {
    const r = w.advance({ untilTime: 2, maxEvents: 20_000 });
    return r.reason === "events" ? "hang" : "no error";
  } catch (e) {
    if (!(e instanceof SimulationError)) throw e;
    return /rests against .* at t=0:/.test(e.message) ? "rest" : e.message;
  }
}

/** A disc of radius 1 touching, from above, a `kind` through (cx, cy) at `deg` degrees down to the right. */
function onRamp(deg: number, kind: "segment" | "line", cx = 0, cy = 0): World {
  const a = (deg * Math.PI) / 180;
  const c = Math.cos(a);
  const s = Math.sin(a);
  const w = new World({ g: 0, gravity: GRAVITY });
  w.addLine("ramp", [cx - 20 * c, cy + 20 * s], [cx + 20 * c, cy - 20 * s], kind);
  w.addBody("ball", { x: cx + s, y: cy + c, r: 1, m: 1 });
  return w;
}

describe("a disc placed touching a slope under gravity", () => {
  it("is refused as resting on every slope of a segment or a line, near the origin or away from it", () => {
    const wrong: string[] = [];
    for (const deg of SLOPES)
      for (const kind of ["segment", "line"] as const)
        for (const [cx, cy] of [
          [0, 0],
          [100, 50],
        ] as const) {
          const o = outcome(onRamp(deg, kind, cx, cy));
          if (o !== "rest") wrong.push(`${deg}° ${kind} at (${cx}, ${cy}): ${o}`);
        }
    expect(wrong).toEqual([]);
  });

  it("is refused as resting on a point, slightly off its top", () => {
    const wrong: string[] = [];
    for (const deg of SLOPES) {
      const a = (deg * Math.PI) / 720; // up to 22.5° off the top
      const w = new World({ g: 0, gravity: GRAVITY });
      w.addPoint("peg", [0, 0]);
      w.addBody("ball", { x: Math.sin(a), y: Math.cos(a), r: 1, m: 1 });
      const o = outcome(w);
      if (o !== "rest") wrong.push(`${deg / 4}°: ${o}`);
    }
    expect(wrong).toEqual([]);
  });

  it("is refused when placed inside the ramp by the slack an edit allows, rising too little to get out", () => {
    // 0.5 OVERLAP_REL inside a 30° ramp, moving out at a speed that rises 1e-12: it stays inside
    const a = Math.PI / 6;
    const n = [Math.sin(a), Math.cos(a)];
    const d = 1 - 0.5 * OVERLAP_REL;
    const up = Math.sqrt(2 * 9.81 * Math.cos(a) * 1e-12);
    const w = new World({ g: 0, gravity: GRAVITY });
    w.addLine(
      "ramp",
      [-20 * Math.cos(a), 20 * Math.sin(a)],
      [20 * Math.cos(a), -20 * Math.sin(a)],
      "segment",
    );
    w.addBody("ball", {
      x: d * (n[0] as number),
      y: d * (n[1] as number),
      r: 1,
      m: 1,
      vx: up * (n[0] as number),
      vy: up * (n[1] as number),
    });
    expect(outcome(w)).toBe("rest");
  });

  it("a Timeline refuses the edit that places it, as on a flat floor, and keeps what it had (10°: prolong hung)", () => {
    const a = Math.PI / 18;
    const tl = new Timeline({ g: 0, gravity: GRAVITY });
    const [c, s] = [Math.cos(a), Math.sin(a)];
    tl.apply({
      time: 0,
      type: "addLine",
      id: "ramp",
      p1: [-20 * c, 20 * s],
      p2: [20 * c, -20 * s],
      kind: "segment",
    });
    const ball = { time: 0, type: "addBody", id: "ball", x: s, y: c, r: 1, m: 1 } as const;
    expect(() => tl.apply(ball)).toThrow(/"ball" rests against "ramp"/);
    expect(tl.actions.map((x) => x.type)).toEqual(["addLine"]);
  });
});

describe("not resting: the same slopes with a real gap or motion", () => {
  it("a disc dropped onto a 30° ramp bounces down it, never inside it", () => {
    const a = Math.PI / 6;
    const [s, c] = [Math.sin(a), Math.cos(a)];
    const w = new World({ g: 0, gravity: GRAVITY });
    w.addLine("ramp", [-40 * c, 40 * s], [40 * c, -40 * s], "segment");
    w.addBody("ball", { x: 1.5 * s, y: 1.5 * c, r: 1, m: 1 }); // half a radius above it
    let hits = 0;
    for (let t = 1 / 64; t <= 2; t += 1 / 64) {
      w.advance({ untilTime: t }, (e) => {
        if (e.kind === "bodyLine") hits++;
      });
      const b = w.body("ball");
      expect(b.x * s + b.y * c).toBeGreaterThanOrEqual(1 - 1e-9); // its distance to the ramp's line
    }
    expect(hits).toBeGreaterThan(1);
  });

  it("a disc gliding along a tilted line with no field goes on along it", () => {
    const a = Math.PI / 7;
    const [s, c] = [Math.sin(a), Math.cos(a)];
    const w = new World({ g: 0 });
    w.addLine("ramp", [-40 * c, 40 * s], [40 * c, -40 * s], "line");
    w.addBody("ball", { x: s, y: c, r: 1, m: 1, vx: c, vy: -s });
    expect(() => w.advance({ untilTime: 20 })).not.toThrow();
    const b = w.body("ball", 20);
    expect(b.x * s + b.y * c).toBeCloseTo(1, 12);
  });
});

describe("a disc crossing a peg at about the speed that keeps it on the peg (restingContact.prop.test.ts, shrunk)", () => {
  /** A disc of radius 0.01 touching a point at `deg` from its top, moving along the contact at vt sqrt(g r). */
  function overPeg(deg: number, gravityDeg: number, vt: number): { w: World; gapOf: () => number } {
    const [r, g] = [0.01, 0.1];
    const a = (deg * Math.PI) / 180;
    const [nx, ny] = [Math.sin(a), Math.cos(a)];
    const ga = (gravityDeg * Math.PI) / 180;
    const w = new World({ g: 0, gravity: [g * Math.sin(ga), -g * Math.cos(ga)] });
    w.addPoint("peg", [0, 0]);
    const speed = Math.sqrt(g * r) * vt;
    w.addBody("ball", { x: r * nx, y: r * ny, r, m: 1, vx: speed * ny, vy: -speed * nx });
    return {
      w,
      gapOf: () => {
        const b = w.body("ball");
        return (Math.hypot(b.x, b.y) - r) / r;
      },
    };
  }

  /** The deepest the disc goes into the peg over 1 s (sampled every ms), or "rest" when refused. */
  function deepest(deg: number, gravityDeg: number, vt: number): number | "rest" {
    const { w, gapOf } = overPeg(deg, gravityDeg, vt);
    let min = 0;
    try {
      for (let k = 1; k <= 1000; k++) {
        w.advance({ untilTime: k / 1000 });
        min = Math.min(min, gapOf());
      }
    } catch (e) {
      if (e instanceof SimulationError && /rests against "peg"/.test(e.message)) return "rest";
      throw e;
    }
    return min;
  }

  it("flying off the peg and back onto it at once: a contact (it fell through: a graze ignored the return)", () => {
    const d = deepest(14.437, 14.039, -0.9375592490555087);
    expect(d === "rest" || d >= -1e-8).toBe(true);
  });

  it("at exactly the speed: sinking into it at third order is a contact now, refused as resting (it fell through)", () => {
    // the pull on the peg, g r cos(32.082°), equals |v|^2 to 15 digits: the second derivative of the
    // gap is a rounding, and the third takes the disc into the peg
    expect(deepest(-32.082, 0, 0.9204829294250664)).toBe("rest");
  });

  it("a rate rounded to just above 0 at the critical speed is a contact, refused (review: it sank 31 % into the peg)", () => {
    const w = new World({ g: 0, gravity: [-0.0224951054343865, -0.09743700647852353] });
    w.addPoint("peg", [0, 0]);
    const at = { x: -0.008571673007021122, y: 0.005150380749100544, r: 0.01, m: 1 };
    w.addBody("ball", { ...at, vx: 0.009053792108789052, vy: 0.015068040444124641 });
    expect(() => w.advance({ untilTime: 1 })).toThrow(/"ball" rests against "peg" .* at t=0:/);
    // 4 ulps faster: the contact was found at once for ever, 65 events at t = 0 and a Zeno error
    const faster = new World({ g: 0, gravity: [-0.0224951054343865, -0.09743700647852353] });
    faster.addPoint("peg", [0, 0]);
    faster.addBody("ball", { ...at, vx: 0.009053792108789073, vy: 0.015068040444124676 });
    let events = 0;
    expect(() =>
      faster.advance({ untilTime: 1 }, () => {
        events++;
      }),
    ).toThrow(/"ball" rests against "peg" .* at t=0:/);
    expect(events).toBe(0);
  });

  it("off the origin (the peg at y = 63): reflected by a rounding's impulse, it stays on, refused (it sank 40 % in)", () => {
    const a = (39.502 * Math.PI) / 180;
    const w = new World({ g: 0, gravity: [0, -0.1] });
    w.addPoint("peg", [0, 63.22839762040087]);
    const v = Math.sqrt(0.1) * -0.8784090047347738;
    w.addBody("ball", {
      x: Math.sin(a),
      y: 63.22839762040087 + Math.cos(a),
      r: 1,
      m: 1,
      vx: v * Math.cos(a),
      vy: -v * Math.sin(a),
    });
    expect(() => w.advance({ untilTime: 10 })).toThrow(/"ball" rests against "peg"/);
  });
});
