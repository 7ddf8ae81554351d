/**
 * The side-by-side rows' timing (bench/lib/settledPasses.mjs): warm-up passes stop once the last
 * three are within 20 % of the fastest, or at the warm-up budget (a long metrics pass counted in it);
 * then at least three timed passes, more while they are cheap, never past the hard budget; the spread
 * is the timed passes' extremes and quartiles. The passes are scripted lists of times, so every
 * stopping rule is checked exactly.
 */
import { describe, expect, it } from "vitest";
import { isSettled, PASS_LIMITS, settledPasses, spreadOf } from "../../bench/lib/settledPasses.mjs";

const MS = 1e6;

/** A pass function returning the given times in order (then the last one forever), and its call count. */
function scripted(timesMs: number[]) {
  let calls = 0;
  const pass = () => {
    const t = (timesMs[Math.min(calls, timesMs.length - 1)] ?? 0) * MS;
    calls++;
    return t;
  };
  return { pass, calls: () => calls };
}

describe("isSettled", () => {
  it("needs a full window, then compares the window's median with the fastest time", () => {
    expect(isSettled([10, 10])).toBe(false);
    expect(isSettled([100, 50, 10])).toBe(false);
    expect(isSettled([100, 50, 10, 11, 12])).toBe(true);
    expect(isSettled([10, 30, 10, 30])).toBe(false); // median of the last three 30: 3x the fastest
    expect(isSettled([10, 12, 12])).toBe(true); // exactly 20 % slower still counts
    expect(isSettled([10, 12.01, 12.01])).toBe(false);
  });
});

describe("settledPasses", () => {
  it("stops the warm-up once settled and times the rest: the JIT's slow first passes never reach the median", () => {
    const s = scripted([120, 80, 35, 9, 10, 9.5, 9, 11, 10]);
    const r = settledPasses(s.pass);
    // settled at [35, 9, 10]: the median of the last three (10) is within 20 % of the fastest (9)
    expect(r.warmup).toEqual({ passes: 5, allNs: [120, 80, 35, 9, 10].map((t) => t * MS), settled: true });
    // timed: 9.5, 9, 11, then 10 ms a pass until 0.2 s are spent or 15 passes
    expect(r.runs).toBe(15);
    expect(r.allNs.slice(0, 4)).toEqual([9.5 * MS, 9 * MS, 11 * MS, 10 * MS]);
    expect(r.medianNs).toBe(10 * MS);
    expect(r.minNs).toBe(9 * MS);
    expect(r.maxNs).toBe(11 * MS);
    expect(s.calls()).toBe(5 + 15);
  });

  it("counts a long metrics pass as the warm-up, and reports settled null when no warm-up pass ran", () => {
    const s = scripted([600]);
    const r = settledPasses(s.pass, { alreadyNs: 600 * MS });
    expect(r.warmup).toEqual({ passes: 0, allNs: [], settled: null });
    expect(r.runs).toBe(PASS_LIMITS.minRuns); // 3 passes of 0.6 s: over the soft budget after the minimum
    expect(s.calls()).toBe(PASS_LIMITS.minRuns);
  });

  it("does not count a short metrics pass: the timed call still warms up for its own budget", () => {
    const s = scripted([200, 150, 150, 150]);
    const r = settledPasses(s.pass, { alreadyNs: 400 * MS }); // under ownWarmupNs (0.5 s)
    // 200 then 150: 0.35 s spent, past the 0.25 s budget, not settled (only two passes)
    expect(r.warmup).toEqual({ passes: 2, allNs: [200 * MS, 150 * MS], settled: false });
  });

  it("gives up warming up at the budget when the times never settle, and says so", () => {
    const s = scripted([10, 40]); // 10, then 40 ms forever: the last three are 4x the fastest
    const r = settledPasses(s.pass, { alreadyNs: 50 * MS }); // a short metrics pass: not counted
    // 10 + 40 * 5 = 210 < 250, one more pass: 250 ms, stop
    expect(r.warmup.passes).toBe(7);
    expect(r.warmup.settled).toBe(false);
  });

  it("gives up warming up after maxWarmup passes however cheap they are", () => {
    const s = scripted([1, 5]);
    const r = settledPasses(s.pass);
    expect(r.warmup.passes).toBe(PASS_LIMITS.maxWarmup);
    expect(r.warmup.settled).toBe(false);
  });

  it("times at least minRuns passes, stops at the hard budget, and always times one", () => {
    const limits = { ...PASS_LIMITS, maxWarmup: 0 };
    expect(settledPasses(scripted([300]).pass, { limits }).runs).toBe(3);
    expect(settledPasses(scripted([1600]).pass, { limits }).runs).toBe(2); // 3.2 s spent after two
    expect(settledPasses(scripted([5000]).pass, { limits }).runs).toBe(1);
    expect(settledPasses(scripted([50]).pass, { limits }).runs).toBe(4); // 0.2 s soft budget reached
  });
});

describe("spreadOf", () => {
  it("gives the extremes, the median and the quartiles of the timed passes", () => {
    expect(spreadOf([5, 1, 4, 2, 3])).toEqual({ medianNs: 3, minNs: 1, q1Ns: 2, q3Ns: 4, maxNs: 5 });
    expect(spreadOf([7])).toEqual({ medianNs: 7, minNs: 7, q1Ns: 7, q3Ns: 7, maxNs: 7 });
  });
});
