import { describe, expect, it } from "vitest";
import { TimelineClient } from "./client";
import type { Port } from "./protocol";

/** A port whose host never answers; `say` delivers a host message to the client. */
function silentPort() {
  const port: Port = { postMessage: () => {}, onmessage: null };
  const say = () =>
    port.onmessage?.({ data: { type: "info", info: { revision: 0 } } as unknown as Record<string, unknown> });
  return { port, say };
}

describe("TimelineClient.stalledFor", () => {
  it("counts from the oldest waiting request or the host's last message, whichever is later", () => {
    const { port, say } = silentPort();
    const client = new TimelineClient(port);
    const t0 = performance.now();
    expect(client.stalledFor(t0 + 10_000)).toBe(0); // nothing waits
    void client.compute(null).catch(() => {});
    const waited = client.stalledFor(t0 + 10_000);
    expect(waited).toBeGreaterThan(9_000);
    // the host reports progress: a waiting request alone does not make it stalled
    // (bounds from the clock read around the message, not a tolerance: a pause there cannot fail it)
    const before = performance.now();
    say();
    const heard = performance.now();
    const stalled = client.stalledFor(heard + 200);
    expect(stalled).toBeGreaterThanOrEqual(200);
    expect(stalled).toBeLessThanOrEqual(200 + (heard - before));
  });
});
