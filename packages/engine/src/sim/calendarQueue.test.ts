// CalendarQueue: the same pop order as a brute-force model, (key, canonical tie order), whatever the
// sequence of inserts, re-keys, removals and peeks, whatever the key scales (the bucket width adapts
// and the window moves on every peek).
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { CalendarQueue } from "./calendarQueue.js";
import { drain } from "./testSupport.js";

const SEED = Number(process.env.FC_SEED ?? 20261122);

/** Tie order of the tests: larger slot first. */
const tieLess = (a: number, b: number): boolean => a > b;

/** The slot a correct queue must show first. */
function modelMin(model: Map<number, number>): number {
  let best = -1;
  let bestKey = Number.POSITIVE_INFINITY;
  for (const [s, k] of model)
    if (best < 0 || k < bestKey || (k === bestKey && tieLess(s, best))) {
      best = s;
      bestKey = k;
    }
  return best;
}

function expectedOrder(model: Map<number, number>): number[] {
  return [...model.entries()].sort((a, b) => a[1] - b[1] || b[0] - a[0]).map(([s]) => s);
}

type Op = { slot: number; key: number } | { remove: number } | { peek: true };

/** Random operations over slots 0..40 with keys from `key`. */
function ops(key: fc.Arbitrary<number>): fc.Arbitrary<Op[]> {
  return fc.array(
    fc.oneof(
      { weight: 6, arbitrary: fc.record({ slot: fc.nat(40), key }) },
      { weight: 1, arbitrary: fc.record({ remove: fc.nat(40) }) },
      { weight: 2, arbitrary: fc.constant({ peek: true as const }) },
    ),
    { minLength: 20, maxLength: 300 },
  );
}

function check(list: Op[]): void {
  const q = new CalendarQueue(4, { tieLess });
  const model = new Map<number, number>();
  for (const o of list) {
    if ("peek" in o) {
      expect(q.peek()).toBe(modelMin(model));
      expect(q.peekKey()).toBe(model.size > 0 ? model.get(modelMin(model)) : Number.POSITIVE_INFINITY);
    } else if ("remove" in o) {
      q.remove(o.remove);
      model.delete(o.remove);
    } else {
      q.reserve(o.slot + 1);
      q.set(o.slot, o.key);
      if (o.key === Number.POSITIVE_INFINITY) model.delete(o.slot);
      else model.set(o.slot, o.key);
    }
    expect(q.size).toBe(model.size);
  }
  expect(drain(q)).toEqual(expectedOrder(model));
}

describe("CalendarQueue", () => {
  it("matches the model when most keys tie (keys from three values)", () => {
    console.log(`[CalendarQueue] fast-check seed ${SEED} (set FC_SEED to change)`);
    fc.assert(fc.property(ops(fc.constantFrom(0, 0.5, 1)), check), { seed: SEED, numRuns: 300 });
  });

  it("matches the model with keys spread over many scales, negative, huge and infinite", () => {
    const key = fc.oneof(
      fc.double({ min: -1e3, max: 1e3, noNaN: true }),
      fc.double({ min: 0, max: 1e-9, noNaN: true }),
      fc.constantFrom(1e300, -1e300, 2 ** 60, Number.POSITIVE_INFINITY, 0, 5e-324),
      fc.integer({ min: 0, max: 100 }).map((i) => 1e6 + i * 1e-9),
    );
    fc.assert(fc.property(ops(key), check), { seed: SEED + 1, numRuns: 300 });
  });

  it("tracks an event-driven workload: the top is re-keyed later, others come and go (many rebuilds)", () => {
    // A deterministic LCG: 2,000 slots, each due at now + an exponential delay whose mean changes
    // by four orders of magnitude during the run, so the width must adapt in both directions.
    let seed = 12345;
    const rnd = (): number => {
      seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
      return (seed + 0.5) / 2 ** 32;
    };
    const n = 2000;
    const q = new CalendarQueue(n, { tieLess });
    const model = new Map<number, number>();
    let now = 0;
    for (let s = 0; s < n; s++) {
      const k = -Math.log(rnd());
      q.set(s, k);
      model.set(s, k);
    }
    const sortedMin = (): number => modelMin(model);
    for (let step = 0; step < 60000; step++) {
      const mean = step < 20000 ? 1 : step < 40000 ? 1e-4 : 3;
      const s = q.peek();
      if (step % 97 === 0) expect(s).toBe(sortedMin());
      const k = q.peekKey();
      expect(k).toBe(model.get(s));
      expect(k).toBeGreaterThanOrEqual(now);
      now = k;
      const next = now + mean * -Math.log(rnd());
      q.set(s, next);
      model.set(s, next);
      // A partner, chosen at random, is re-keyed too (a collision moves two bodies).
      const o = Math.floor(rnd() * n);
      const ko = now + mean * -Math.log(rnd());
      q.set(o, ko);
      model.set(o, ko);
    }
    // The width followed the delays: rebuilt when they shrank and when they grew again.
    expect(q.diagnostics().rebuilds).toBeGreaterThanOrEqual(2);
    expect(drain(q)).toEqual(expectedOrder(model));
  });

  it("an entry pulled from the overflow at the window's far edge waits for its turn", () => {
    const q = new CalendarQueue(8, { tieLess });
    // The first peek sizes the queue from the keys queued; then the window is buckets [0, nb).
    for (let s = 0; s < 4; s++) q.set(s, s);
    expect(q.peek()).toBe(0);
    const { width: w, origin, buckets: nb } = q.diagnostics();
    expect(nb).toBe(16);
    for (let s = 0; s < 4; s++) q.remove(s);
    const at = (bucket: number): number => origin + (bucket + 0.5) * w;
    // A starts in the overflow (bucket 1.5 nb). When the window moves on at bucket nb/2 it ends at
    // bucket 1.5 nb, which shares its ring slot with bucket nb/2: A must stay in the overflow and
    // not be loaded with bucket nb/2, before C (bucket nb/2 + 1).
    q.set(5, at(1.5 * nb));
    q.set(6, at(1));
    q.set(7, at(nb / 2 + 1));
    expect(q.peek()).toBe(6);
    q.remove(6);
    expect(q.peek()).toBe(7);
    q.remove(7);
    expect(q.peek()).toBe(5);
    expect(q.diagnostics().rebuilds).toBe(1);
  });

  it("a fresh queue is sized once, at its first peek, from every key queued so far", () => {
    const q = new CalendarQueue(4, { tieLess });
    for (let s = 0; s < 1000; s++) {
      q.reserve(s + 1);
      q.set(s, (s * 7919) % 1000);
    }
    expect(q.diagnostics().rebuilds).toBe(0);
    expect(q.peek()).toBe(0);
    expect(q.diagnostics()).toMatchObject({ rebuilds: 1, buckets: 2048 });
  });

  it("refuses a NaN time by name instead of corrupting the order", () => {
    const q = new CalendarQueue(4, { tieLess });
    expect(() => q.set(2, Number.NaN)).toThrow(/slot 2 .*NaN/);
    expect(q.size).toBe(0);
  });

  it("a clone pops the same order as its original and is independent of it", () => {
    const q = new CalendarQueue(64, { tieLess });
    for (let s = 0; s < 64; s++) q.set(s, (s * 37) % 11);
    q.peek();
    const c = q.cloneWith({ tieLess });
    q.set(5, -1);
    expect(c.peek()).not.toBe(5);
    const model = new Map<number, number>();
    for (let s = 0; s < 64; s++) model.set(s, (s * 37) % 11);
    expect(drain(c)).toEqual(expectedOrder(model));
  });
});
