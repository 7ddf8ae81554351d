// The Zeno watch alone: runs of simultaneous events, windows that make too little progress, and
// its counters carried through save/load.
import { describe, expect, it } from "vitest";
import {
  SIMULTANEOUS_EVENTS_PER_BODY,
  ZENO_MIN_PROGRESS,
  ZENO_WINDOW_EVENTS,
  ZENO_WINDOW_EVENTS_PER_BODY,
} from "../tolerances.js";
import { SimulationError } from "./errors.js";
import { ZenoWatch } from "./zenoWatch.js";

const never = () => false;
const always = () => true;

describe("ZenoWatch", () => {
  it("allows SIMULTANEOUS_EVENTS_PER_BODY * n events at one instant and throws at the next", () => {
    const n = 3;
    const z = new ZenoWatch();
    const limit = SIMULTANEOUS_EVENTS_PER_BODY * n;
    for (let i = 0; i <= limit; i++) z.check(5, n, never);
    expect(() => z.check(5, n, never)).toThrow(SimulationError);
    expect(() => z.check(5, n, never)).toThrow(/at the same instant t=5/);
  });

  it("starts a new run when time moves on", () => {
    const z = new ZenoWatch();
    const runs = () => {
      for (let k = 0; k < 10; k++)
        for (let i = 0; i <= SIMULTANEOUS_EVENTS_PER_BODY; i++) z.check(k, 1, never);
    };
    expect(runs).not.toThrow();
  });

  it("a window with too little progress throws only while energy can be fed in", () => {
    const window = Math.max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY * 2);
    const step = (ZENO_MIN_PROGRESS / window) * 0.5; // distinct instants, too close together
    const run = (pumps: () => boolean) => {
      const z = new ZenoWatch();
      let t = 1;
      const next = () => {
        t += step;
        z.check(t, 2, pumps);
      };
      // The first window has no start time (-Infinity): it only sets one.
      for (let i = 0; i < 2 * window - 1; i++) next();
      return next;
    };
    expect(run(always)).toThrow(/events accumulate at a finite time/);
    expect(run(never)).not.toThrow();
  });

  it("a window that makes progress passes", () => {
    const window = Math.max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY);
    const z = new ZenoWatch();
    let t = 0;
    const run = () => {
      for (let i = 0; i < 3 * window; i++) {
        t += 1e-3;
        z.check(t, 1, always);
      }
    };
    expect(run).not.toThrow();
  });

  it("has no unit of time: the same events with times × 2^-40 or × 2^40 throw at the same event", () => {
    // Windows of events 1 apart from t = 1 (progress 200,000 >> 1e-6 |t|), then converging on
    // a finite time by steps shrinking 1e-4 per event; scaled by k, every comparison is the same.
    const window = Math.max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY);
    const throwsAt = (k: number): number => {
      const z = new ZenoWatch();
      let t = 1;
      let step = 1;
      for (let i = 0; i < 6 * window; i++) {
        if (i >= 3 * window) step *= 0.9999;
        t += step;
        try {
          z.check(t * k, 1, always);
        } catch {
          return i;
        }
      }
      return -1;
    };
    const at = throwsAt(1);
    expect(at).toBeGreaterThan(3 * window);
    expect(throwsAt(2 ** -40)).toBe(at);
    expect(throwsAt(2 ** 40)).toBe(at);
  });

  it("save and load carry the counters: a restored watch throws at the same event", () => {
    const n = 1;
    const a = new ZenoWatch();
    for (let i = 0; i < SIMULTANEOUS_EVENTS_PER_BODY; i++) a.check(2, n, never);
    const b = new ZenoWatch();
    b.load(a.save());
    expect(b.save()).toEqual(a.save());
    a.check(2, n, never);
    b.check(2, n, never);
    expect(() => a.check(2, n, never)).toThrow(SimulationError);
    expect(() => b.check(2, n, never)).toThrow(SimulationError);
    const fresh = new ZenoWatch();
    fresh.check(2, n, never);
    fresh.check(2, n, never);
    expect(() => fresh.check(2, n, never)).not.toThrow();
  });
});
