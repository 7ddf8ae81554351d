// The calendar queue's width: when its buckets have drifted far enough to rebuild, and the width
// and ring length a rebuild picks from the queued keys.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { CALENDAR_BUCKET_TARGET, CALENDAR_REBUILD_FACTOR } from "../tolerances.js";
import { bucketWidth, rebuildDue, ringLength } from "./calendarWidth.js";

const SEED = Number(process.env.FC_SEED ?? 20261122);

describe("rebuildDue", () => {
  const high = CALENDAR_BUCKET_TARGET * CALENDAR_REBUILD_FACTOR;
  const low = CALENDAR_BUCKET_TARGET / CALENDAR_REBUILD_FACTOR;

  it("waits for 64 buckets, however far off the loads are", () => {
    expect(rebuildDue(63, 63 * 100, 0, 1000)).toBe(false);
    expect(rebuildDue(63, 0, 1e9, 1000)).toBe(false);
    expect(rebuildDue(64, 64 * 100, 0, 1000)).toBe(true);
  });

  it("rebuilds when the entries per bucket leave [target / factor, target * factor]", () => {
    expect(rebuildDue(100, 100 * high, 0, 1000)).toBe(false);
    expect(rebuildDue(100, 100 * high + 1, 0, 1000)).toBe(true);
    expect(rebuildDue(100, 100 * low, 0, 1000)).toBe(false);
    expect(rebuildDue(100, 100 * low - 1, 0, 1000)).toBe(true);
    expect(rebuildDue(100, 100 * CALENDAR_BUCKET_TARGET, 0, 1000)).toBe(false);
  });

  it("rebuilds when the overflow has been scanned more than 8 times over (plus 1,024)", () => {
    const perBucket = 100 * CALENDAR_BUCKET_TARGET;
    expect(rebuildDue(100, perBucket, 8 * 1000 + 1024, 1000)).toBe(false);
    expect(rebuildDue(100, perBucket, 8 * 1000 + 1025, 1000)).toBe(true);
  });
});

describe("bucketWidth", () => {
  it("puts about the target number of entries per bucket for keys spread like an exponential", () => {
    console.log(`[calendarWidth] fast-check seed ${SEED} (set FC_SEED to change)`);
    fc.assert(
      fc.property(
        fc.integer({ min: 50, max: 5000 }),
        fc.double({ min: 1e-6, max: 1e6, noNaN: true }),
        fc.double({ min: -1e6, max: 1e6, noNaN: true }),
        (n, tau, start) => {
          // The n quantiles of an exponential of mean tau from `start`: n / tau entries fall due
          // per unit of time, so w n / tau of them per bucket.
          const keys = Float64Array.from({ length: n }, (_, i) => start - tau * Math.log(1 - (i + 0.5) / n));
          const perBucket = (bucketWidth(keys) * n) / tau;
          expect(perBucket).toBeGreaterThan(CALENDAR_BUCKET_TARGET * 0.9);
          expect(perBucket).toBeLessThan(CALENDAR_BUCKET_TARGET * 1.1);
        },
      ),
      { seed: SEED, numRuns: 200 },
    );
  });

  it("gives 0 (no usable width) for no keys, one key, equal keys or a width whose inverse overflows", () => {
    expect(bucketWidth(new Float64Array(0))).toBe(0);
    expect(bucketWidth(Float64Array.of(7))).toBe(0);
    expect(bucketWidth(Float64Array.of(3, 3, 3, 3))).toBe(0);
    expect(bucketWidth(Float64Array.of(0, 0, 5e-324, 5e-324))).toBe(0);
    expect(bucketWidth(Float64Array.of(0, 0, 1, 1))).toBeGreaterThan(0);
  });
});

describe("ringLength", () => {
  it("is the smallest power of two of at least 16 and at least 2 n", () => {
    expect(ringLength(0)).toBe(16);
    expect(ringLength(8)).toBe(16);
    expect(ringLength(9)).toBe(32);
    expect(ringLength(16)).toBe(32);
    expect(ringLength(17)).toBe(64);
    for (let n = 0; n < 5000; n += 37) {
      const nb = ringLength(n);
      expect(nb & (nb - 1)).toBe(0);
      expect(nb).toBeGreaterThanOrEqual(Math.max(16, 2 * n));
      expect(nb === 16 || nb / 2 < 2 * n).toBe(true);
    }
  });
});
