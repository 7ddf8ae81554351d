// The scene rules look for overlaps near the action (sim/obstacleCells.ts for a disc among lines and
// points, DiscGrid.smallestNearSegment for a line or point among the discs): every action is refused,
// or not, exactly as a scan of every body, line and point refuses it (the same SceneError, path and
// reason, naming the same smallest id), with positions known and forgotten, on touching pairs
// (within OVERLAP_REL and just past it), tiny radii and far-off coordinates. The scan:
// test/sceneScan.ts.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { Scan, type ScanBody } from "../../test/sceneScan.js";
import {
  placementFarEnd as farEnd,
  placementFrame as frame,
  type PlacementPlace as Place,
  placementPlace as place,
  placementPointStep as pointStep,
} from "../sim/testSupport.js";
import { seedFor } from "../timeline/testSupport.js";
import { SceneError } from "./errors.js";
import { checkAndApply, SceneView } from "./sceneRules.js";
import type { Action, LineKind, Vec2 } from "./types.js";

const kind = fc.constantFrom("segment", "segment", "segment", "ray", "line") as fc.Arbitrary<LineKind>;
const step = fc.oneof(
  {
    arbitrary: fc.record({
      op: fc.constant("addBody" as const),
      place,
      rho: fc.constantFrom(0.3, 1, 2.5, 1e-9),
    }),
    weight: 4,
  },
  {
    arbitrary: fc.record({
      op: fc.constant("moveBody" as const),
      which: fc.nat(200),
      place,
      x: fc.boolean(),
    }),
    weight: 2,
  },
  {
    arbitrary: fc.record({
      op: fc.constant("growBody" as const),
      which: fc.nat(200),
      rho: fc.constantFrom(0.5, 2, 6),
    }),
    weight: 1,
  },
  {
    arbitrary: fc.record({
      op: fc.constant("line" as const),
      id: fc.integer({ min: 0, max: 47 }),
      d: farEnd,
      kind,
      place,
    }),
    weight: 4,
  },
  { arbitrary: pointStep, weight: 3 },
  {
    arbitrary: fc.record({
      op: fc.constant("remove" as const),
      id: fc.integer({ min: 0, max: 47 }),
      what: fc.constantFrom("line", "point", "body"),
    }),
    weight: 1,
  },
  { arbitrary: fc.constant({ op: "forget" as const }), weight: 1 },
);
type Step = typeof step extends fc.Arbitrary<infer S> ? S : never;

/** Where `p` puts a disc of radius r (or a point: r = 0) in the scanned scene. */
function where(s: Scan, f: { o: number; s: number }, p: Place, r: number): Vec2 {
  const lattice: Vec2 = [f.o + f.s * p.u[0], f.o + f.s * p.u[1]];
  const pick = <T>(map: Map<string, T>): T | undefined => [...map.values()][p.near % Math.max(1, map.size)];
  if (p.near < 0) return lattice;
  let c: Vec2 | undefined;
  let reach = r;
  if (p.what === "body") {
    const b = pick(s.bodies);
    if (b !== undefined) {
      c = [b.x, b.y];
      reach = r + b.r;
    }
  } else if (p.what === "line") {
    const l = pick(s.lines);
    if (l !== undefined) c = [l.p1[0] + p.end * (l.p2[0] - l.p1[0]), l.p1[1] + p.end * (l.p2[1] - l.p1[1])];
  } else c = pick(s.points);
  if (c === undefined) return lattice;
  const d = Math.max(reach, f.s * 0.5) * (1 + p.gap);
  return [c[0] + d * Math.cos(p.angle * (Math.PI / 2)), c[1] + d * Math.sin(p.angle * (Math.PI / 2))];
}

/** The action a step makes, with valid ids (undefined: none). */
function actionOf(s: Scan, f: { o: number; s: number }, st: Step, n: number): Action | undefined {
  const time = s.time;
  const ids = [...s.bodies.keys()];
  const body = (k: number) => ids[k % Math.max(1, ids.length)];
  switch (st.op) {
    case "addBody": {
      const r = f.s * st.rho;
      const [x, y] = where(s, f, st.place, r);
      return { time, type: "addBody", id: `n${n}`, x, y, r, m: 1 };
    }
    case "moveBody": {
      const id = body(st.which);
      if (id === undefined) return undefined;
      const [x, y] = where(s, f, st.place, (s.bodies.get(id) as ScanBody).r);
      return st.x ? { time, type: "updateBody", id, x } : { time, type: "updateBody", id, x, y };
    }
    case "growBody": {
      const id = body(st.which);
      return id === undefined ? undefined : { time, type: "updateBody", id, r: f.s * st.rho };
    }
    case "line": {
      const id = `l${st.id}`;
      const p1 = where(s, f, st.place, 0);
      const p2: Vec2 = [p1[0] + f.s * st.d[0], p1[1] + f.s * st.d[1]];
      if (p1[0] === p2[0] && p1[1] === p2[1]) return undefined;
      return s.lines.has(id)
        ? { time, type: "updateLine", id, p1, p2, kind: st.kind }
        : { time, type: "addLine", id, p1, p2, kind: st.kind };
    }
    case "point": {
      const id = `p${st.id}`;
      const p = where(s, f, st.place, 0);
      return { time, type: s.points.has(id) ? "updatePoint" : "addPoint", id, p };
    }
    case "remove": {
      const id = st.what === "body" ? body(st.id) : `${st.what === "line" ? "l" : "p"}${st.id}`;
      const has =
        st.what === "body" ? id !== undefined : (st.what === "line" ? s.lines : s.points).has(id as string);
      if (!has) return undefined;
      const type = st.what === "body" ? "removeBody" : st.what === "line" ? "removeLine" : "removePoint";
      return { time, type, id: id as string };
    }
    default:
      return undefined;
  }
}

/** 50 discs 4 units apart, 40 short walls and 40 points between them (enough for the index). */
function baseActions(f: { o: number; s: number; rho: number }): Action[] {
  const at = (u: number): number => f.o + f.s * u;
  const out: Action[] = [];
  for (let i = 0; i < 50; i++)
    out.push({
      time: 0,
      type: "addBody",
      id: `b${i}`,
      x: at(4 * (i % 10) - 20),
      y: at(4 * Math.floor(i / 10) - 8),
      r: f.s * f.rho,
      m: 1,
    });
  for (let k = 0; k < 40; k++) {
    const u = 4 * (k % 10) - 18;
    const v = 4 * Math.floor(k / 10) - 6;
    out.push({
      time: 0,
      type: "addLine",
      id: `l${k}`,
      p1: [at(u - 1), at(v)],
      p2: [at(u), at(v)],
      kind: "segment",
    });
    out.push({ time: 0, type: "addPoint", id: `p${k}`, p: [at(u), at(v)] });
  }
  return out;
}

describe("scene rules near the action", () => {
  it("refuse exactly what a scan refuses (property)", () => {
    let refused = 0;
    fc.assert(
      fc.property(frame, fc.array(step, { minLength: 1, maxLength: 60 }), (f, steps) => {
        const view = new SceneView(0, 0, [0, 0]);
        const scan = new Scan();
        const base = baseActions(f);
        let n = 0;
        const check = (a: Action) => {
          const path = `actions[${n}]`;
          const want = scan.apply(a);
          let got: string | undefined;
          try {
            checkAndApply(view, a, path);
          } catch (e) {
            if (!(e instanceof SceneError)) throw e;
            expect(e.path).toBe(path);
            got = e.reason;
          }
          if (got !== undefined) refused++;
          expect(got).toBe(want);
        };
        for (const a of base) check(a);
        for (const st of steps) {
          n++;
          if (st.op === "forget") {
            scan.time++;
            for (const b of scan.bodies.values()) b.known = false;
            view.forgetPositions(scan.time);
            continue;
          }
          const a = actionOf(scan, f, st, n);
          if (a === undefined) continue;
          check(a);
        }
      }),
      { seed: seedFor("scene rules near the action against a scan"), numRuns: 120 },
    );
    expect(refused).toBeGreaterThan(100);
  });
});
