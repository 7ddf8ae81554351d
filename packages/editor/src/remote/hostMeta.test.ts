// The host's op `meta`: the scene's meta replaced, nothing recomputed, kept per timeline.
import { newtonsCradle } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { fakeClockHost } from "../testing/fakeHost";

describe("TimelineHost op meta", () => {
  it("replaces the scene's meta and sends the scene again, leaving the history as it was", () => {
    const { host, run, infos } = fakeClockHost({ ...newtonsCradle(), meta: { title: "old", view: 1 } });
    host.handle({ id: 1, op: "compute", until: { time: 5 } });
    run();
    const before = infos().at(-1)!;
    expect(before.horizon).toBe(5);
    host.handle({ id: 2, op: "meta", meta: { title: "new" } });
    const after = infos().at(-1)!;
    expect(after.doc?.meta).toEqual({ title: "new" });
    expect(after.docRevision).toBe(before.docRevision + 1);
    expect([after.horizon, after.eventCount, after.computing]).toEqual([5, before.eventCount, null]);
    const first = infos().find((i) => i.doc !== null)!.doc!;
    expect(first.meta).toEqual({ title: "old", view: 1 });
    expect(after.doc?.actions).toEqual(first.actions);
    host.handle({ id: 3, op: "meta", meta: null });
    expect(infos().at(-1)!.doc?.meta).toBeUndefined();
    // a scene loaded brings its own meta
    host.handle({ id: 4, op: "load", scene: { ...newtonsCradle(), meta: { title: "loaded" } } });
    expect(infos().at(-1)!.doc?.meta).toEqual({ title: "loaded" });
  });
});
