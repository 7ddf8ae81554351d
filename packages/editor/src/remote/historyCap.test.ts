// A computation stops once the stored history passes HISTORY_MAX_BYTES, saying why (∞ on a scene
// that never comes to rest grew to 1.6 GB and ended in "Array buffer allocation failed": review,
// session 19); the history up to there stands, and a computation asked later says the same.
import { bouncingBalls } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { fakeClockHost } from "../testing/fakeHost";
import { HISTORY_MAX_BYTES } from "./hostCompute";

/** A host whose timeline counts each logged entry as 1 MiB of history (the cap in 512 entries). */
function heavyHost(initial: SceneFile = bouncingBalls()) {
  const { host, run, infos } = fakeClockHost(initial, (tl) => ({
    historyBytes: () => tl.eventCount * 2 ** 20,
  }));
  return { host, run, info: () => infos().at(-1)! };
}

describe("the history cap", () => {
  it("∞ on balls bouncing for ever stops past HISTORY_MAX_BYTES, saying why, the history kept", () => {
    const { host, run, info } = heavyHost();
    host.handle({ id: 1, op: "compute", until: null });
    run();
    const i = info();
    expect(i.computing).toBeNull();
    expect(i.stopped).toMatch(
      /^the history holds \d+ MiB \(\d+ entries\), more than the 512 MiB the editor keeps/,
    );
    expect(i.historyBytes).toBeGreaterThan(HISTORY_MAX_BYTES);
    expect(i.eventCount).toBeLessThan(2 * (HISTORY_MAX_BYTES / 2 ** 20));
    expect(i.horizon).toBeGreaterThan(0);
    // asked again, it stops at once with the same words, the history unchanged
    const horizon = i.horizon;
    host.handle({ id: 2, op: "compute", until: { time: 100 } });
    run();
    expect(info().stopped).toMatch(/^the history holds/);
    expect(info().horizon).toBe(horizon);
  });
});
