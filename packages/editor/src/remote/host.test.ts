import { dilutedGas, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { fakeClockHost } from "../testing/fakeHost";
import { crushScene } from "../testing/scenes";
import { TimelineHost } from "./host";
import { packFrame } from "./packFrame";
import type { Frame, HostMessage, TimelineInfo } from "./protocol";

/** A host on a fake clock (testing/fakeHost.ts) over a 60-disc gas by default. */
function fakeHost(initial: SceneFile = dilutedGas({ n: 60, packing: 0.3, seed: 5 })) {
  return fakeClockHost(initial);
}

describe("TimelineHost while computing", () => {
  it("reports progress at most every INFO_EVERY_MS, and frames carry the revision last reported", () => {
    const { host, tasks, sent, infos } = fakeHost();
    host.handle({ id: 1, op: "compute", until: { time: 40 } });
    const before = infos().length;
    let rounds = 0;
    let checkedFrame = false;
    while (tasks.length > 0) {
      tasks.shift()!();
      rounds++;
      if (rounds === 7) {
        host.handle({ id: 2, op: "frame", t: 0.5, window: 0 });
        const reply = sent[sent.length - 1]!;
        expect(reply.type).toBe("reply");
        const f = (reply as { value: Frame }).value;
        expect(f.revision).toBe(infos().at(-1)!.revision);
        checkedFrame = true;
      }
    }
    const during = infos().length - before;
    expect(checkedFrame).toBe(true);
    expect(rounds).toBeGreaterThan(20); // the job took many rounds...
    expect(during).toBeLessThan(rounds / 3); // ...and far fewer progress reports
    const last = infos().at(-1)!;
    expect(last.computing).toBeNull();
    expect(last.horizon).toBe(40);
  });
});

describe("TimelineHost on an edit in the past", () => {
  it("answers at once, then recomputes the cut history to the old horizon in slices, with progress, and a compute-ahead request does not cut it short", () => {
    const { host, tasks, sent, infos } = fakeHost();
    host.handle({ id: 1, op: "compute", until: { time: 40 } });
    while (tasks.length > 0) tasks.shift()!();
    const reference = Timeline.fromScene(dilutedGas({ n: 60, packing: 0.3, seed: 5 }), { compute: false });
    const edit = { time: 3, type: "giveVelocity" as const, id: "d0", v: [1, 2] as [number, number] };
    reference.apply(edit);
    reference.prolongTo(40);

    host.handle({ id: 2, op: "apply", actions: [edit] });
    expect(sent.at(-1)).toEqual({ type: "reply", id: 2, ok: true, value: null });
    const after = infos().at(-1)!;
    expect(after.horizon).toBe(3); // the edit itself was computed, not the 37 s after it
    expect(after.computing).toMatchObject({ targetTime: 40, startHorizon: 3 });
    // The editor asks to compute 10 s ahead after each edit: the recomputation to 40 s covers it.
    host.handle({ id: 3, op: "compute", until: { time: 10 } });
    expect(infos().at(-1)!.computing).toMatchObject({ targetTime: 40 });

    let rounds = 0;
    const horizons: number[] = [];
    while (tasks.length > 0) {
      tasks.shift()!();
      rounds++;
      horizons.push(infos().at(-1)!.horizon);
    }
    expect(rounds).toBeGreaterThan(5); // in slices, reporting progress between them
    expect(new Set(horizons).size).toBeGreaterThan(2);
    const last = infos().at(-1)!;
    expect(last.computing).toBeNull();
    expect(last.horizon).toBe(40);
    expect(last.eventCount).toBe(reference.eventCount);
    host.handle({ id: 4, op: "frame", t: 40, window: 0 });
    const frame = (sent.at(-1) as { value: Frame }).value;
    expect(Array.from(frame.data)).toEqual(Array.from(packFrame(reference.stateAt(40), 0).data));
  });
});

describe("TimelineHost frames", () => {
  it("played forwards and backwards, with an edit between, equal packFrame(stateAt(t)), ids sent only when they change", () => {
    const { host, tasks, sent } = fakeHost();
    host.handle({ id: 1, op: "compute", until: { time: 10 } });
    while (tasks.length > 0) tasks.shift()!();
    const reference = Timeline.fromScene(dilutedGas({ n: 60, packing: 0.3, seed: 5 }), { compute: false });
    reference.prolongTo(10);
    let id = 2;
    const frameAt = (t: number): Frame & { ids: string[] | null } => {
      host.handle({ id: id++, op: "frame", t, window: 0 });
      return (sent.at(-1) as { value: Frame & { ids: string[] | null } }).value;
    };
    const check = (times: number[]) => {
      for (const t of times) {
        const f = frameAt(t);
        const expected = packFrame(reference.stateAt(t), f.revision);
        expect(Array.from(f.data), `t = ${t}`).toStrictEqual(Array.from(expected.data));
        expect({ ...f, data: null, ids: null }).toStrictEqual({ ...expected, data: null, ids: null });
      }
    };
    const first = frameAt(0);
    expect(first.ids).toHaveLength(60);
    check([0.25, 0.5, 1, 2, 4, 8, 10, 9.5, 3, 0]);
    expect(frameAt(5).ids).toBeNull(); // the same 60 ids: the client keeps its copy
    const edit = { time: 4, type: "removeBody" as const, id: "d7" };
    reference.apply(edit);
    reference.prolongTo(10);
    host.handle({ id: id++, op: "apply", actions: [edit] });
    while (tasks.length > 0) tasks.shift()!();
    expect(frameAt(3.9).ids).toBeNull();
    expect(frameAt(4.1).ids).toHaveLength(59);
    check([4.2, 6, 10, 1]);
  });
});

describe("TimelineHost on a second edit while the first one's history is recomputed", () => {
  it("recomputes up to the horizon the user had, not to where the first recomputation had got", () => {
    // Audit (session 15): two quick edits at t = 0.5 of a history computed to 40 s left it at 11.66 s.
    const { host, tasks, infos } = fakeHost();
    host.handle({ id: 1, op: "compute", until: { time: 40 } });
    while (tasks.length > 0) tasks.shift()!();
    host.handle({ id: 2, op: "apply", actions: [{ time: 0.5, type: "giveVelocity", id: "d0", v: [1, 2] }] });
    for (let i = 0; i < 3; i++) tasks.shift()!();
    const partial = infos().at(-1)!;
    expect(partial.horizon).toBeLessThan(40);
    expect(partial.computing).toMatchObject({ targetTime: 40, restore: true });
    host.handle({ id: 3, op: "apply", actions: [{ time: 0.6, type: "giveVelocity", id: "d1", v: [2, 1] }] });
    expect(infos().at(-1)!.computing).toMatchObject({ targetTime: 40, restore: true });
    while (tasks.length > 0) tasks.shift()!();
    expect(infos().at(-1)!).toMatchObject({ horizon: 40, computing: null });
  });

  it("a computation asked as a restore (the editor's recompute after an undo) says so", () => {
    const { host, infos } = fakeHost();
    host.handle({ id: 1, op: "compute", until: { time: 5 }, restore: true });
    expect(infos().at(-1)!.computing).toMatchObject({ targetTime: 5, restore: true });
    // a later time asked meanwhile takes it over and brings that history back too: still a restore
    host.handle({ id: 2, op: "compute", until: { time: 50 } });
    expect(infos().at(-1)!.computing).toMatchObject({ targetTime: 50, restore: true });
    // a count of events says nothing of where it ends: not a restore
    host.handle({ id: 3, op: "compute", until: { events: 10 } });
    expect(infos().at(-1)!.computing).toMatchObject({ targetEvents: 10, restore: false });
    host.handle({ id: 4, op: "compute", until: { time: 60 } });
    expect(infos().at(-1)!.computing).toMatchObject({ targetTime: 60, restore: false });
  });
});

describe("TimelineHost when the engine refuses to go on", () => {
  it("a Zeno state met while computing ends the computation with its message; the history stays readable", () => {
    const zeno = crushScene();
    const tasks: (() => void)[] = [];
    const sent: HostMessage[] = [];
    let clock = 0;
    const host = new TimelineHost(
      (scene) => Timeline.fromScene(scene, { compute: false }),
      { post: (m) => sent.push(m), schedule: (fn) => tasks.push(fn), now: () => (clock += 0.05) },
      zeno,
    );
    host.handle({ id: 1, op: "compute", until: null });
    let rounds = 0;
    while (tasks.length > 0 && rounds < 100_000) {
      expect(() => tasks.shift()!()).not.toThrow();
      rounds++;
    }
    const infos = sent.filter((m): m is { type: "info"; info: TimelineInfo } => m.type === "info");
    const last = infos.at(-1)!.info;
    expect(last.computing).toBeNull();
    expect(last.stopped).toMatch(/Zeno/);
    expect(last.horizon).toBeGreaterThan(1.9);
    expect(last.horizon).toBeLessThan(2);
    host.handle({ id: 2, op: "frame", t: 1, window: 0 });
    expect(sent.at(-1)).toMatchObject({ type: "reply", id: 2, ok: true });
    // a new computation clears the message
    host.handle({ id: 3, op: "apply", actions: [{ time: 0.5, type: "removeBody", id: "crusher" }] });
    expect(sent.filter((m) => m.type === "info").at(-1)).toMatchObject({ info: { stopped: null } });
  });
});
