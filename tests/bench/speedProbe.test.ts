/**
 * The benchmark's machine speed probe (bench/lib/speedProbe.mjs) and its report paragraph
 * (bench/report/speedProbe.mjs): the spread is slowest / fastest − 1 per workload, a run is steady
 * only when both spreads are within the threshold, and the report says which in plain words.
 */
import { describe, expect, it } from "vitest";
import { probeHere, SPREAD_WARN, summarizeProbes } from "../../bench/lib/speedProbe.mjs";
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
