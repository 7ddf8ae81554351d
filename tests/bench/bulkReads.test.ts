/**
 * The report's bulk-read rows (bench/report/bulkReads.mjs): each read with its time as objects and
 * as arrays and their ratio, the heap bytes of one read each, an error said as such, and nothing for
 * a run from before the rows existed (so the committed report stays what it was).
 */
import { describe, expect, it } from "vitest";
import { bulkReadsBlock } from "../../bench/report/bulkReads.mjs";

describe("bulk reads in the report", () => {
  it("gives each read's time as objects and as arrays with their ratio, and the bytes of one read", () => {
    const out: string[] = [];
    bulkReadsBlock(
      {
        bulkReads: {
          bodies: 20000,
          events: 60004,
          horizon: 2.2351,
          reads: 30,
          passes: 3,
          rows: [
            { api: "Timeline", order: "forwards", objectsNs: 4.2e6, arraysNs: 6e5 },
            { api: "Timeline", order: "backwards", objectsNs: 4e6, arraysNs: 2e6 },
            { api: "World", order: "now", objectsNs: 1.7e7, arraysNs: 1.25e6 },
          ],
          allocation: { stateAt: 7337272, bodyArraysAt: 78912, bodies: 5473664, bodyArrays: 3512 },
        },
      },
      out,
    );
    const text = out.join("\n");
    expect(text).toContain(
      "One read of all 20,000 discs of a 10 % gas (60,004 events computed, horizon 2.24 s)",
    );
    expect(text).toContain(
      "| Timeline: stateAt(t) vs bodyArraysAt(t, into) | forwards (playback) | 4.2 ms | 0.6 ms | 7× |",
    );
    expect(text).toContain(
      "| Timeline: stateAt(t) vs bodyArraysAt(t, into) | backwards (each read replays from the keyframe) | 4 ms | 2 ms | 2× |",
    );
    expect(text).toContain(
      "| World: bodies(t) vs bodyArrays(t, into) | at its current time | 17 ms | 1.25 ms | 13.6× |",
    );
    expect(text).toContain(
      "stateAt 7,337,272 bytes, bodyArraysAt 78,912; World.bodies 5,473,664, bodyArrays 3,512.",
    );
  });

  it("says an error, and gives nothing for a run without the rows", () => {
    const failed: string[] = [];
    bulkReadsBlock({ bulkReads: { error: "Timeline.bodyArraysAt is not in this engine" } }, failed);
    expect(failed.join("\n")).toContain("Not measured: Timeline.bodyArraysAt is not in this engine");
    const none: string[] = [];
    bulkReadsBlock({}, none);
    expect(none).toStrictEqual([]);
  });
});
