/**
 * Determinism of the incremental paths: a gas (frictionless, or with friction) built one action
 * per apply (reads in between or not: the keyframe after an instant's actions is owed until
 * something needs it, checkpoint.ts), then edits at the horizon's instant one call at a time, edits of the last action there taken
 * back and given again the editor's way (setActions without it, prolongTo, apply: the spare
 * restart point, restartPoint.ts), edits at earlier instants, all give the log, counts, states
 * and event details that building the final action list from scratch gives, bit for bit.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import type { Action } from "../scene/types.js";
import { seedFor, speed } from "./testSupport.js";
import { Timeline } from "./timeline.js";

const RUNS = Number(process.env.RUNS ?? 12);
const EDITOR = { keepHorizon: false, checkLater: false };

type Op =
  | { kind: "push"; who: number; v: [number, number] }
  | { kind: "move"; who: number; v: [number, number] }
  | { kind: "wall" }
  | { kind: "merge"; v: [number, number] }
  | { kind: "drop" }
  | { kind: "later"; events: number }
  | { kind: "past"; which: number; who: number; v: [number, number] }
  | { kind: "read" };

const vel = fc.tuple(speed, speed);
const edit: fc.Arbitrary<Op> = fc.oneof(
  fc.record({ kind: fc.constant("push" as const), who: fc.nat(), v: vel }),
  fc.record({ kind: fc.constant("move" as const), who: fc.nat(), v: vel }),
  fc.record({ kind: fc.constant("wall" as const) }),
);
const ending: fc.Arbitrary<Op[]> = fc.oneof(
  fc.constant<Op[]>([]),
  vel.map((v): Op[] => [{ kind: "merge", v }]),
  fc.constant<Op[]>([{ kind: "drop" }]),
  fc.constant<Op[]>([{ kind: "drop" }, { kind: "drop" }]),
  fc.tuple(fc.nat(), fc.nat(), vel).map(([which, who, v]): Op[] => [{ kind: "past", which, who, v }]),
);
/** A burst at the horizon's instant: 1 to 4 edits, each read after or not (the editor reads after
 *  each), then a merge, take-backs or an edit at an earlier instant, then the horizon moves on. */
const burst: fc.Arbitrary<Op[]> = fc
  .tuple(
    fc.array(fc.tuple(edit, fc.boolean()), { minLength: 1, maxLength: 4 }),
    ending,
    fc.integer({ min: 0, max: 300 }),
  )
  .map(([edits, end, events]) => [
    ...edits.flatMap(([e, read]): Op[] => (read ? [e, { kind: "read" }] : [e])),
    ...end,
    ...(events > 0 ? [{ kind: "later" as const, events }] : []),
  ]);
const ops: fc.Arbitrary<Op[]> = fc.array(burst, { minLength: 1, maxLength: 4 }).map((b) => b.flat());

/** Apply `ops` to `tl` (see the header); returns the instants the actions went to. */
function run(tl: Timeline, n: number, ops: readonly Op[]): number[] {
  const instants: number[] = [0];
  let walls = 0;
  const id = (who: number) => `d${who % n}`;
  for (const o of ops) {
    const t = tl.horizon;
    if (o.kind === "push") tl.apply({ time: t, type: "giveVelocity", id: id(o.who), v: o.v }, EDITOR);
    else if (o.kind === "move") tl.apply({ time: t, type: "updateBody", id: id(o.who), v: o.v }, EDITOR);
    else if (o.kind === "wall") {
      const y = -1000 - 3 * walls;
      tl.apply(
        { time: t, type: "addLine", id: `x${walls++}`, kind: "segment", p1: [0, y], p2: [2, y] },
        EDITOR,
      );
    } else if (o.kind === "merge" || o.kind === "drop") {
      const list = tl.actions.slice();
      const last = list.pop() as Action;
      if (last.time === 0) continue; // keep the scene itself
      tl.setActions(list);
      tl.prolongTo(last.time);
      if (o.kind === "merge" && (last.type === "giveVelocity" || last.type === "updateBody"))
        tl.apply({ ...last, v: o.v }, EDITOR);
    } else if (o.kind === "later") tl.prolong({ events: o.events });
    else if (o.kind === "past") {
      const at = instants[o.which % instants.length] as number;
      tl.apply({ time: at, type: "giveVelocity", id: id(o.who), v: o.v }, EDITOR);
    } else tl.stateAt(t);
    if (!instants.includes(tl.horizon)) instants.push(tl.horizon);
  }
  return instants;
}

describe("incremental and from-scratch builds give the same history", () => {
  it("applies one at a time, edits at the horizon, take-backs and merges equal fromScene of the actions", () => {
    const seed = seedFor("incremental");
    fc.assert(
      fc.property(
        fc.integer({ min: 8, max: 60 }),
        fc.integer({ min: 1, max: 1000 }),
        fc.boolean(),
        fc.constantFrom(0, 0.001),
        fc.array(fc.boolean(), { minLength: 1, maxLength: 70 }),
        ops,
        (n, gasSeed, compute, mu, reads, steps) => {
          // frictionless, or with friction (stops, g = 1)
          const gas = dilutedGas({ n, packing: 0.15, seed: gasSeed });
          const s = {
            ...gas,
            g: mu > 0 ? 1 : gas.g,
            actions: gas.actions.map((a) => (a.type === "addBody" ? { ...a, mu } : a)),
          };
          const tl = new Timeline({ g: s.g, gravity: s.gravity, compute });
          s.actions.forEach((a, i) => {
            tl.apply(a);
            if (reads[i % reads.length]) tl.stateAt(0);
          });
          tl.prolong({ events: 200 });
          const instants = run(tl, n, steps);
          const end = Math.max(tl.horizon, ...instants);
          tl.prolongTo(end);
          const scratch = Timeline.fromScene(tl.toScene());
          scratch.prolongTo(end);
          expect(tl.horizon).toBe(scratch.horizon);
          expect(tl.eventCount).toBe(scratch.eventCount);
          expect(tl.counts()).toStrictEqual(scratch.counts());
          expect(tl.eventsBetween(0, end)).toStrictEqual(scratch.eventsBetween(0, end));
          for (const t of [...instants, end / 3, end])
            expect(tl.stateAt(t)).toStrictEqual(scratch.stateAt(t));
          for (let i = 0; i < tl.eventCount; i++)
            if (tl.event(i).type === "action")
              expect(tl.eventDetail(i)).toStrictEqual(scratch.eventDetail(i));
        },
      ),
      { seed, numRuns: RUNS, verbose: true },
    );
  });
});
