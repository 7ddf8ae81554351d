// The World's placement checks look near the edit (obstacleCells.ts for a disc among lines and
// points, bodiesNear.ts for a line or point among the grid's bodies): every edit is refused, or not,
// exactly as a scan of every body, line and point refuses it (the same ChapgameError, path and
// reason, naming the same smallest id), before and after the bodies move, with the grid and without,
// on touching pairs (within OVERLAP_REL and just past it), tiny radii and far-off coordinates.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { seedFor } from "../timeline/testSupport.js";
import { OVERLAP_REL } from "../tolerances.js";
import { ChapgameError } from "./errors.js";
import { distanceToLine, type LineKind, makeLine } from "./obstacles.js";
import {
  placementFarEnd as farEnd,
  placementFrame as frame,
  type PlacementPlace as Place,
  placementPlace as place,
  placementPointStep as pointStep,
  placementUnit as unit,
} from "./testSupport.js";
import type { BodyState, Vec2 } from "./types.js";
import { World } from "./world.js";

const KEEP = 1 - OVERLAP_REL;

/** The refusal a scan of everything gives (the pre-index code's tests, in its order), or "ok". */
function scanRefusal(w: World, edit: Edit): string {
  const bodies = w.bodies();
  const smallest = <T>(list: readonly T[], id: (t: T) => string, hit: (t: T) => boolean) => {
    let best: string | undefined;
    for (const t of list) if ((best === undefined || id(t) < best) && hit(t)) best = id(t);
    return best;
  };
  const discRefusal = (x: number, y: number, r: number, self: string | null, field: string) => {
    const body = smallest(
      bodies,
      (b) => b.id,
      (b) => {
        const R = (r + b.r) * KEEP;
        return b.id !== self && (b.x - x) ** 2 + (b.y - y) ** 2 < R * R;
      },
    );
    if (body !== undefined) return `${field}: the body would overlap body "${body}"`;
    const rk = r * KEEP;
    const line = smallest(
      w.lines(),
      (l) => l.id,
      (l) => distanceToLine(makeLine(l.id, l.p1, l.p2, l.kind), x, y) < rk,
    );
    if (line !== undefined) return `${field}: the body would overlap line "${line}"`;
    const point = smallest(
      w.points(),
      (p) => p.id,
      (p) => (p.p[0] - x) * (p.p[0] - x) + (p.p[1] - y) * (p.p[1] - y) < rk * rk,
    );
    return point !== undefined ? `${field}: the body would overlap point "${point}"` : "ok";
  };
  const bodyHit = (hit: (b: BodyState) => boolean) => smallest(bodies, (b) => b.id, hit);
  switch (edit.op) {
    case "addBody":
      return discRefusal(edit.x, edit.y, edit.r, null, "x");
    case "updateBody": {
      const b = bodies.find((c) => c.id === edit.id) as BodyState;
      const x = edit.x ?? b.x;
      const y = edit.y ?? b.y;
      const r = edit.r ?? b.r;
      if (x === b.x && y === b.y && r === b.r) return "ok";
      return discRefusal(x, y, r, edit.id, x !== b.x ? "x" : y !== b.y ? "y" : "r");
    }
    case "line": {
      const old = w.lines().find((l) => l.id === edit.id);
      const line = makeLine(edit.id, edit.p1, edit.p2, edit.kind);
      const moved = (p: Vec2, q: Vec2 | undefined) => q === undefined || p[0] !== q[0] || p[1] !== q[1];
      const field =
        old === undefined || moved(edit.p1, old.p1)
          ? "p1"
          : moved(edit.p2, old.p2)
            ? "p2"
            : edit.kind !== old.kind
              ? "kind"
              : "p1";
      const hit = bodyHit((b) => distanceToLine(line, b.x, b.y) < b.r * KEEP);
      return hit === undefined ? "ok" : `${field}: the line would overlap body "${hit}"`;
    }
    case "point": {
      const [x, y] = edit.p;
      const hit = bodyHit((b) => (b.x - x) ** 2 + (b.y - y) ** 2 < (b.r * KEEP) ** 2);
      return hit === undefined ? "ok" : `p: the point would lie inside body "${hit}"`;
    }
  }
}

type Edit =
  | { op: "addBody"; id: string; x: number; y: number; r: number }
  | { op: "updateBody"; id: string; x?: number; y?: number; r?: number }
  | { op: "line"; id: string; p1: Vec2; p2: Vec2; kind: LineKind }
  | { op: "point"; id: string; p: Vec2 };

/** Apply `edit` to the World: "ok" or the refusal (which must be a ChapgameError). */
function apply(w: World, edit: Edit): string {
  try {
    if (edit.op === "addBody") w.addBody(edit.id, { x: edit.x, y: edit.y, r: edit.r, m: 1 });
    else if (edit.op === "updateBody") {
      const patch: { x?: number; y?: number; r?: number } = {};
      if (edit.x !== undefined) patch.x = edit.x;
      if (edit.y !== undefined) patch.y = edit.y;
      if (edit.r !== undefined) patch.r = edit.r;
      w.updateBody(edit.id, patch);
    } else if (edit.op === "line") {
      if (w.hasLine(edit.id)) w.updateLine(edit.id, { p1: edit.p1, p2: edit.p2, kind: edit.kind });
      else w.addLine(edit.id, edit.p1, edit.p2, edit.kind);
    } else if (w.hasPoint(edit.id)) w.updatePoint(edit.id, edit.p);
    else w.addPoint(edit.id, edit.p);
    return "ok";
  } catch (e) {
    if (!(e instanceof ChapgameError)) throw e;
    return `${e.path}: ${e.reason}`;
  }
}

const step = fc.oneof(
  {
    arbitrary: fc.record({
      op: fc.constant("addBody" as const),
      place,
      rho: fc.constantFrom(0.3, 1, 2.5, 1e-9),
    }),
    weight: 4,
  },
  { arbitrary: fc.record({ op: fc.constant("moveBody" as const), which: fc.nat(200), place }), weight: 2 },
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
      a: fc.tuple(unit, unit),
      b: farEnd,
      kind: fc.constantFrom("segment", "segment", "segment", "ray", "line") as fc.Arbitrary<LineKind>,
      place,
    }),
    weight: 4,
  },
  { arbitrary: pointStep, weight: 3 },
  {
    arbitrary: fc.record({
      op: fc.constant("remove" as const),
      id: fc.integer({ min: 0, max: 47 }),
      line: fc.boolean(),
    }),
    weight: 1,
  },
  { arbitrary: fc.record({ op: fc.constant("advance" as const), dt: fc.constantFrom(0.4, 1.3) }), weight: 1 },
);
type Step = typeof step extends fc.Arbitrary<infer S> ? S : never;

/**
 * A World of 72 discs (the grid is used from 64) on a lattice 4 units apart, some moving, and 36
 * short walls and 36 points between them (enough for the obstacles' index: 32 of a kind).
 */
function base(f: { o: number; s: number; rho: number }, broadPhase: boolean): World {
  const w = new World({ optimizations: { broadPhase } });
  const at = (u: number): number => f.o + f.s * u;
  for (let i = 0; i < 72; i++) {
    const u = 4 * (i % 9) - 16;
    const v = 4 * Math.floor(i / 9) - 16;
    const vx = i % 3 === 0 ? f.s * ((i % 5) - 2) : 0;
    w.addBody(`b${i}`, { x: at(u), y: at(v), r: f.s * f.rho, m: 1, vx, vy: f.s * ((i % 4) - 1.5) });
  }
  for (let k = 0; k < 36; k++) {
    const u = 4 * (k % 6) - 14;
    const v = 4 * Math.floor(k / 6) - 14;
    w.addLine(`l${k}`, [at(u - 2), at(v)], [at(u - 1), at(v)], "segment");
    w.addPoint(`p${k}`, [at(u), at(v)]);
  }
  return w;
}

/** Where `place` puts a disc of radius r (or a point: r = 0) in `w`. */
function where(w: World, f: { o: number; s: number }, p: Place, r: number): Vec2 {
  const lattice: Vec2 = [f.o + f.s * p.u[0], f.o + f.s * p.u[1]];
  if (p.near < 0) return lattice;
  let c: Vec2 | undefined;
  let reach = r;
  if (p.what === "body") {
    const bodies = w.bodies();
    const b = bodies[p.near % bodies.length] as BodyState;
    c = [b.x, b.y];
    reach = r + b.r;
  } else if (p.what === "line") {
    const lines = w.lines();
    const l = lines[p.near % Math.max(1, lines.length)];
    if (l !== undefined) c = [l.p1[0] + p.end * (l.p2[0] - l.p1[0]), l.p1[1] + p.end * (l.p2[1] - l.p1[1])];
  } else {
    const pts = w.points();
    const q = pts[p.near % Math.max(1, pts.length)];
    if (q !== undefined) c = q.p;
  }
  if (c === undefined) return lattice;
  const d = Math.max(reach, f.s * 0.5) * (1 + p.gap);
  return [c[0] + d * Math.cos(p.angle * (Math.PI / 2)), c[1] + d * Math.sin(p.angle * (Math.PI / 2))];
}

/** The edit a step makes (undefined: none, e.g. a line whose ends coincide there). */
function editOf(w: World, f: { o: number; s: number }, st: Step, n: number): Edit | undefined {
  const ids = w.bodies().map((b) => b.id);
  switch (st.op) {
    case "addBody": {
      const r = f.s * st.rho;
      const [x, y] = where(w, f, st.place, r);
      return { op: "addBody", id: `n${n}`, x, y, r };
    }
    case "moveBody": {
      const id = ids[st.which % ids.length] as string;
      const r = (w.bodies().find((b) => b.id === id) as BodyState).r;
      const [x, y] = where(w, f, st.place, r);
      return { op: "updateBody", id, x, y };
    }
    case "growBody":
      return { op: "updateBody", id: ids[st.which % ids.length] as string, r: f.s * st.rho };
    case "line": {
      const p1 = where(w, f, st.place, 0);
      const p2: Vec2 = [p1[0] + f.s * (st.b[0] - st.a[0]), p1[1] + f.s * (st.b[1] - st.a[1])];
      if (p1[0] === p2[0] && p1[1] === p2[1]) return undefined;
      return { op: "line", id: `l${st.id}`, p1, p2, kind: st.kind };
    }
    case "point":
      return { op: "point", id: `p${st.id}`, p: where(w, f, st.place, 0) };
    default:
      return undefined;
  }
}

describe("placement checks near the edit", () => {
  for (const broadPhase of [true, false])
    it(`refuse exactly what a scan refuses (${broadPhase ? "with" : "without"} the grid) (property)`, () => {
      let refused = 0;
      fc.assert(
        fc.property(frame, fc.array(step, { minLength: 1, maxLength: 40 }), (f, steps) => {
          const w = base(f, broadPhase);
          let n = 0;
          for (const st of steps) {
            n++;
            if (st.op === "advance") {
              try {
                w.advance({ untilTime: w.time + st.dt });
              } catch {
                return; // a state the model cannot continue from: nothing more to check here
              }
              continue;
            }
            if (st.op === "remove") {
              const id = `${st.line ? "l" : "p"}${st.id}`;
              if (st.line && w.hasLine(id)) w.removeLine(id);
              if (!st.line && w.hasPoint(id)) w.removePoint(id);
              continue;
            }
            const edit = editOf(w, f, st, n);
            if (edit === undefined) continue;
            const want = scanRefusal(w, edit);
            const got = apply(w, edit);
            if (got !== "ok") refused++;
            expect(got).toBe(want);
          }
        }),
        { seed: seedFor(`placement near the edit against a scan (grid ${broadPhase})`), numRuns: 60 },
      );
      expect(refused).toBeGreaterThan(100);
    });
});
