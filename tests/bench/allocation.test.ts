// bench/lib/allocation.mjs: it counts what a function allocates, and little for a function that
// allocates nothing.
import { describe, expect, it } from "vitest";
import { allocatedBytes } from "../../bench/lib/allocation.mjs";

describe("allocatedBytes", () => {
  it("sees 100,000 objects (at least 16 bytes each) and almost nothing for arithmetic in place", async () => {
    // Kept in a list, so that no optimisation can prove them unused and drop the allocation.
    const kept: { i: number }[] = [];
    const objects = await allocatedBytes(() => {
      for (let i = 0; i < 100_000; i++) kept.push({ i });
    });
    const out = new Float64Array(1024);
    const arithmetic = (): void => {
      for (let i = 0; i < 100_000; i++) out[i & 1023] = (out[i & 1023] as number) * 0.5 + i;
    };
    // Compiled first: V8's first tiers box doubles, and how long they run depends on the machine's
    // load (review: 3 runs in 10 failed on a busy machine without this).
    arithmetic();
    arithmetic();
    const inPlace = await allocatedBytes(arithmetic);
    expect(kept.length).toBe(100_000);
    expect(objects).toBeGreaterThan(100_000 * 16);
    expect(inPlace).toBeLessThan(objects / 20);
  });
});
