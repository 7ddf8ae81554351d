/**
 * The report's mixed-radii rows (bench/report/mixedRadii.mjs): each big-disc radius with its rate
 * relative to the gas without a big disc, an error row kept in place, the rows of many large discs
 * against the same gas, and nothing for a run from before the rows existed.
 */
import { describe, expect, it } from "vitest";
import { mixedRadiiBlock } from "../../bench/report/mixedRadii.mjs";

const row = (bigR: number, eventsPerSecond: number, bigEventShare: number) => ({
  bigR,
  n: 10000,
  batch: 200000,
  runs: 3,
  eventsPerSecond,
  bigEventShare,
});

describe("mixed radii in the report", () => {
  it("gives each radius's rate against the gas without a big disc, and keeps an error row", () => {
    const out: string[] = [];
    mixedRadiiBlock(
      {
        mixedRadii: {
          rows: [row(1, 300000, 0.0002), row(20, 240000, 0.002), { bigR: 100, n: 10000, error: "boom" }],
        },
      },
      out,
    );
    const text = out.join("\n");
    expect(text).toContain("| 1 | 200,000 | 3 | 300,000 | 0.02 % | 1× |");
    expect(text).toContain("| 20 | 200,000 | 3 | 240,000 | 0.2 % | 0.8× |");
    expect(text).toContain("| 100 |  |  | error: boom |  |  |");
  });

  it("gives each radius law's rate against the gas of radius 1 alone; no second table without its rows", () => {
    const out: string[] = [];
    const rows = [row(1, 400000, 0.0001)];
    mixedRadiiBlock(
      {
        mixedRadii: {
          rows,
          manyRows: [
            { law: "100 discs r = 20", n: 10000, batch: 200000, runs: 3, eventsPerSecond: 160000 },
            { law: "r log-uniform 1 to 30", n: 10000, error: "no room" },
          ],
        },
      },
      out,
    );
    const text = out.join("\n");
    expect(text).toContain("many large discs");
    expect(text).toContain("| 100 discs r = 20 | 200,000 | 3 | 160,000 | 0.4× |");
    expect(text).toContain("| r log-uniform 1 to 30 |  |  | error: no room |  |");
    const old: string[] = [];
    mixedRadiiBlock({ mixedRadii: { rows } }, old);
    expect(old.join("\n")).not.toContain("many large discs");
  });

  it("writes nothing for a run from before the rows existed", () => {
    const out: string[] = [];
    mixedRadiiBlock({}, out);
    expect(out).toEqual([]);
  });
});
