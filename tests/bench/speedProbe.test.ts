/**
 * The benchmark's machine speed probe (bench/lib/speedProbe.mjs) and its report paragraph
 * (bench/report/speedProbe.mjs): the spread is slowest / fastest − 1 per workload, a run is steady
 * only when both spreads are within the threshold, and the report says which in plain words.
 */
import { describe, expect, it } from "vitest";
import {
  probeHere,
  probeWhenSteady,
  SLOW_BY,
  SPREAD_WARN,
  slowerThanEarlier,
  summarizeProbes,
  WAIT_MAX_S,
  WAIT_STEP_S,
} from "../../bench/lib/speedProbe.mjs";
import { speedProbeBlock, speedProbeNote } from "../../bench/report/speedProbe.mjs";

const probe = (at: string, walkNs: number, fpNs: number) => ({ at, walkNs, fpNs });

describe("speed probe summary", () => {
  it("takes the spread of each workload and the larger of the two", () => {
    const s = summarizeProbes([
      probe("before solver", 10, 6),
      probe("before engine", 11, 6.3),
      probe("at the end", 10.5, 6),
    ]);
    expect(s.walk).toEqual({ minNs: 10, maxNs: 11, spread: 11 / 10 - 1 });
    expect(s.fp.spread).toBeCloseTo(0.05, 12);
    expect(s.spread).toBe(s.walk.spread);
    expect(s.steady).toBe(true);
  });

  it("is not steady when either workload slowed beyond the threshold", () => {
    const fpSlow = summarizeProbes([probe("a", 10, 6), probe("b", 10, 6 * (1 + SPREAD_WARN) * 1.01)]);
    expect(fpSlow.steady).toBe(false);
    const walkSlow = summarizeProbes([probe("a", 10, 6), probe("b", 10 * (1 + SPREAD_WARN) * 1.01, 6)]);
    expect(walkSlow.steady).toBe(false);
  });

  it("measures both workloads in this process as positive finite times", () => {
    const p = probeHere();
    expect(p.walkNs).toBeGreaterThan(0);
    expect(p.fpNs).toBeGreaterThan(0);
    expect(Number.isFinite(p.walkNs + p.fpNs)).toBe(true);
  });
});

describe("speed probe in the report", () => {
  it("lists every probe and says the speed held, or warns that absolute times are suspect", () => {
    const steady = {
      speedProbe: summarizeProbes([probe("before solver", 9.5, 6.1), probe("at the end", 9.9, 6.2)]),
    };
    const text = speedProbeBlock(steady).join("\n");
    expect(text).toContain("| before solver | 9.50 | 6.10 |");
    expect(text).toContain("| at the end | 9.90 | 6.20 |");
    expect(text).toContain("no slow spell beyond it showed");
    expect(speedProbeNote(steady)).toBe(
      " Machine speed probes spread 4 % during the run (warning above 25 %).",
    );
    const slow = {
      speedProbe: summarizeProbes([probe("before solver", 9.5, 6.1), probe("at the end", 14, 6.2)]),
    };
    expect(speedProbeBlock(slow).join("\n")).toContain("absolute times are suspect");
    expect(speedProbeNote(slow)).toContain("changed by 47 %");
  });

  it("writes nothing for a run from before the probe existed", () => {
    expect(speedProbeBlock({})).toEqual([]);
    expect(speedProbeNote({})).toBe("");
  });
});

describe("waiting out a slow spell before a section", () => {
  const earlier = [probe("before solver", 9, 6), probe("before peers", 10, 5.5)];
  const slowWalk = 9 * (1 + SLOW_BY) * 1.01;

  it("calls a probe slow when either workload is over SLOW_BY slower than the fastest earlier one", () => {
    expect(slowerThanEarlier(probe("x", 9 * (1 + SLOW_BY) * 0.99, 6), earlier)).toBe(false);
    expect(slowerThanEarlier(probe("x", slowWalk, 5.5), earlier)).toBe(true);
    expect(slowerThanEarlier(probe("x", 9, 5.5 * (1 + SLOW_BY) * 1.01), earlier)).toBe(true);
    expect(slowerThanEarlier(probe("x", 100, 100), [])).toBe(false);
  });

  /** A fake probe that reads the given walk times in turn, and a sleep that only counts. */
  function fakes(walks: number[]) {
    const slept: number[] = [];
    let i = 0;
    return {
      slept,
      io: {
        probe: (at: string) => probe(at, walks[Math.min(i++, walks.length - 1)] as number, 5.5),
        sleepS: async (s: number) => {
          slept.push(s);
        },
      },
    };
  }

  it("probes again after each wait until the speed is back, and records the slow probes", async () => {
    const f = fakes([slowWalk, slowWalk, 9.2]);
    const r = await probeWhenSteady("before engine", earlier, 0, f.io);
    expect(r.probe.walkNs).toBe(9.2);
    expect(f.slept).toEqual([WAIT_STEP_S, WAIT_STEP_S]);
    expect(r.wait).toEqual({
      before: "before engine",
      seconds: 2 * WAIT_STEP_S,
      slowProbes: [probe("before engine", slowWalk, 5.5), probe("before engine", slowWalk, 5.5)],
      gaveUp: false,
    });
  });

  it("does not wait at normal speed, nor with nothing earlier to compare with", async () => {
    const normal = fakes([9.5]);
    expect((await probeWhenSteady("before engine", earlier, 0, normal.io)).wait).toBeNull();
    const first = fakes([slowWalk]);
    expect((await probeWhenSteady("before solver", [], 0, first.io)).wait).toBeNull();
    expect([...normal.slept, ...first.slept]).toEqual([]);
  });

  it("stops waiting at WAIT_MAX_S over the whole run and says it measured while slow", async () => {
    const f = fakes([slowWalk]);
    const spent = WAIT_MAX_S - WAIT_STEP_S - 5;
    const r = await probeWhenSteady("before stress", earlier, spent, f.io);
    expect(f.slept).toEqual([WAIT_STEP_S, 5]);
    expect(r.wait?.seconds).toBe(WAIT_STEP_S + 5);
    expect(r.wait?.gaveUp).toBe(true);
    const text = speedProbeBlock({
      speedProbe: summarizeProbes([...earlier, r.probe], r.wait ? [r.wait] : []),
    });
    expect(text.join("\n")).toContain(`This run waited ${WAIT_STEP_S + 5} s: before stress: probed at walk`);
    expect(text.join("\n")).toContain("measured anyway");
  });
});
