import { Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { Action, SceneFile, Until } from "../engineTypes";
import { boxScene } from "../testing/scenes";
import { TimelineHost } from "./host";
import type { HostMessage, TimelineInfo } from "./protocol";
import type { TimelineLike } from "./timelineLike";

/**
 * An edit the engine refuses at once, sent while the host computes ahead: it changes nothing, so
 * the computation runs on and its end is reported. The host used to drop the running job without
 * a word: the client showed "computing" for ever (editorUndoSequences, seed 704378602: an edit
 * refused while the editor computed ahead, then "host did not settle").
 */
const box: SceneFile = boxScene([]);

/** A host on a manual schedule: every prolongSlice computes at most one event. */
function slowHost() {
  const tasks: (() => void)[] = [];
  const sent: HostMessage[] = [];
  let clock = 0;
  const factory = (scene: SceneFile): TimelineLike => {
    const tl = Timeline.fromScene(scene, { compute: false });
    const slice = tl.prolongSlice.bind(tl);
    return Object.assign(tl, { prolongSlice: (u: Until, budget: number) => slice(u, Math.min(budget, 1)) });
  };
  const host = new TimelineHost(
    factory,
    { post: (m) => sent.push(m), schedule: (fn) => tasks.push(fn), now: () => (clock += 1) },
    box,
  );
  const run = (steps = 100_000) => {
    for (let k = 0; k < steps && tasks.length > 0; k++) tasks.shift()!();
  };
  const infos = () =>
    sent.filter((m): m is { type: "info"; info: TimelineInfo } => m.type === "info").map((m) => m.info);
  const reply = (id: number) => sent.find((m) => m.type === "reply" && m.id === id);
  return { host, sent, run, infos, reply };
}

describe("TimelineHost: an edit refused at once while computing ahead", () => {
  it("leaves the computation running, and its end is reported", () => {
    const h = slowHost();
    h.host.handle({ id: 1, op: "compute", until: { time: 400 } });
    h.run(1); // one round: the computation is under way
    const during = h.infos().at(-1)!;
    expect(during.computing).toMatchObject({ targetTime: 400 });
    expect(during.horizon).toBeLessThan(400);
    const bad: Action = { time: 1, type: "addBody", id: "z", x: 50, y: 50, r: -1, m: 1 };
    h.host.handle({ id: 2, op: "apply", actions: [bad] });
    expect(h.reply(2)).toMatchObject({ ok: false, error: { path: "action.r" } });
    h.run();
    const reference = Timeline.fromScene(box, { compute: false });
    reference.prolongTo(400);
    expect(h.infos().at(-1)!).toMatchObject({
      horizon: 400,
      computing: null,
      eventCount: reference.eventCount,
    });
  });

  it("after a refused edit with nothing computing, reports nothing computing", () => {
    const h = slowHost();
    h.host.handle({ id: 1, op: "compute", until: { time: 5 } });
    h.run();
    expect(h.infos().at(-1)!).toMatchObject({ horizon: 5, computing: null });
    const posted = h.sent.length;
    const bad: Action = { time: 1, type: "addBody", id: "z", x: 50, y: 50, r: -1, m: 1 };
    h.host.handle({ id: 2, op: "apply", actions: [bad] });
    expect(h.reply(2)).toMatchObject({ ok: false });
    h.run();
    expect(h.sent.length).toBe(posted + 1); // the refusal alone: no info, no computation started
  });
});
