// A restore job's target h + (T - h) can round one unit below T (7.52 + (42.88 - 7.52) is
// 42.879999999999995): a check whose last later action is at exactly T then ended without applying
// it, and the refused edit was answered OK (review of session 15).
import { Timeline } from "@chapgame/engine";
import { expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import { boxScene } from "../testing/scenes";
import { TimelineHost } from "./host";
import type { HostMessage, TimelineInfo } from "./protocol";

const T = 42.88; // 7.52 + (42.88 - 7.52) === 42.879999999999995
const box: SceneFile = boxScene(
  [{ time: T, type: "addBody", id: "e", x: 50, y: 50, r: 1, m: 1 }],
  [
    ["a", 3, 3, [2, 1.3]],
    ["b", 10, 4, [-1.1, 2]],
  ],
);

it("an edit in the past whose last later action is at the old horizon is checked against it", () => {
  const tasks: (() => void)[] = [];
  const sent: HostMessage[] = [];
  let clock = 0;
  const host = new TimelineHost(
    (s) => Timeline.fromScene(s, { compute: false }),
    { post: (m) => sent.push(m), schedule: (fn) => tasks.push(fn), now: () => (clock += 0.001) },
    box,
  );
  const run = () => {
    for (let k = 0; k < 100_000 && tasks.length > 0; k++) tasks.shift()!();
  };
  host.handle({ id: 1, op: "compute", until: { time: T } });
  run();
  const info = () => (sent.filter((m) => m.type === "info").at(-1) as { info: TimelineInfo }).info;
  expect(info().horizon).toBe(T);
  // z sits where e is added at T: the edit must be refused
  host.handle({
    id: 2,
    op: "apply",
    actions: [{ time: 7.52, type: "addBody", id: "z", x: 50, y: 50.5, r: 1, m: 1 }],
  });
  run();
  const reply = sent.find((m) => m.type === "reply" && m.id === 2);
  expect(reply).toMatchObject({
    ok: false,
    error: {
      message: expect.stringMatching(
        /^actions\[6\]: body "e" would overlap body "z" at time 42\.88 \(once this action is in place\)$/,
      ),
    },
  });
  // taken back: the old history again, up to T exactly, not idle
  expect(info()).toMatchObject({ horizon: T, idle: false, computing: null });
});
