/**
 * The report's rows of a scene built one action per call at successive instants
 * (bench/report/instants.mjs): each scene and history setting with its time per N and the growth of
 * the time per apply, an error said as such, and nothing for a run from before the rows existed (so
 * the committed report stays what it was).
 */
import { describe, expect, it } from "vitest";
import { instantsBlock } from "../../bench/report/instants.mjs";

describe("one action per instant in the report", () => {
  it("gives each scene's build times per N and how the time per apply grows", () => {
    const out: string[] = [];
    const points = (a: number, b: number) => [
      { n: 1000, ms: a },
      { n: 8000, ms: b },
    ];
    instantsBlock(
      {
        instants: {
          runs: 3,
          dt: 0.01,
          rows: [
            { scene: "resting", history: true, points: points(263, 939), scaling: 0.446 },
            { scene: "thrown", history: false, points: points(177, 515), scaling: 0.3637 },
          ],
        },
      },
      out,
    );
    const text = out.join("\n");
    expect(text).toContain("one per call at t = 0, 0.01, 0.02, …");
    expect(text).toContain("each time is the median of 3 fresh builds");
    expect(text).toContain("the time per apply at N = 8,000 over that at N = 1,000: 1 is linear.");
    expect(text).toContain("| scene | history | N = 1,000 | N = 8,000 | per apply, largest / smallest N |");
    expect(text).toContain("| discs at rest on a lattice | yes | 263 ms | 939 ms | 0.446× |");
    expect(text).toContain("| discs thrown under friction | no | 177 ms | 515 ms | 0.364× |");
  });

  it("gives the reads over such a history per N, and no reads table for a run without them", () => {
    const row = { scene: "thrown" as const, history: true, points: [{ n: 2000, ms: 300 }], scaling: 1 };
    const reads = {
      count: 40,
      passes: 5,
      rows: [
        {
          n: 2000,
          events: 3943,
          historyBytes: 1251891,
          ways: [
            { name: "stateAt", order: "backwards", ms: 0.2123 },
            { name: "path", order: "whole history", ms: 1.007 },
          ],
        },
      ],
    };
    const out: string[] = [];
    instantsBlock({ instants: { runs: 3, dt: 0.01, rows: [row], reads } }, out);
    const text = out.join("\n");
    expect(text).toContain("at 40 times spread over it");
    expect(text).toContain("the median of 5 passes");
    expect(text).toContain("| N | events | history | stateAt, backwards | path, whole history |");
    expect(text).toContain("| 2,000 | 3,943 | 1.25 MB | 0.212 ms | 1.01 ms |");
    const without: string[] = [];
    instantsBlock({ instants: { runs: 3, dt: 0.01, rows: [row] } }, without);
    expect(without.join("\n")).not.toContain("Reads over such a history");
  });

  it("says an error, and gives nothing for a run without the rows", () => {
    const failed: string[] = [];
    instantsBlock({ instants: { error: "body d3 would overlap body d0" } }, failed);
    expect(failed.join("\n")).toContain("Not measured: body d3 would overlap body d0");
    const none: string[] = [];
    instantsBlock({}, none);
    expect(none).toStrictEqual([]);
  });
});
