/**
 * A TimelineHost on a fake clock, for the host's tests: computing takes 0.5 ms per event, every
 * reading of the clock 0.01 ms, and scheduled rounds run when the test says (`tasks`, or `run` for
 * all of them). `tweak` may replace parts of each timeline the host makes (a history that counts
 * as larger, say). With the real engine's Timeline.
 */
import { Timeline } from "@chapgame/engine";
import type { SceneFile, Until } from "../engineTypes";
import { TimelineHost } from "../remote/host";
import type { HostMessage, TimelineInfo } from "../remote/protocol";
import type { TimelineLike } from "../remote/timelineLike";

export function fakeClockHost(
  initial: SceneFile,
  tweak: (tl: Timeline) => Partial<TimelineLike> = () => ({}),
) {
  let clock = 0;
  const tasks: (() => void)[] = [];
  const sent: HostMessage[] = [];
  const factory = (scene: SceneFile): TimelineLike => {
    const tl = Timeline.fromScene(scene, { compute: false });
    const slice = tl.prolongSlice.bind(tl);
    return Object.assign(tl, {
      prolongSlice: (until: Until, budget: number) => {
        const r = slice(until, budget);
        clock += 0.5 * r.events;
        return r;
      },
      ...tweak(tl),
    });
  };
  const host = new TimelineHost(
    factory,
    {
      post: (m) => sent.push(m),
      schedule: (fn) => tasks.push(fn),
      now: () => {
        clock += 0.01;
        return clock;
      },
    },
    initial,
  );
  const infos = () =>
    sent.filter((m): m is { type: "info"; info: TimelineInfo } => m.type === "info").map((m) => m.info);
  /** Runs the scheduled rounds until none is left (at most 10,000). */
  const run = () => {
    for (let k = 0; k < 10_000 && tasks.length > 0; k++) tasks.shift()!();
  };
  return { host, tasks, sent, infos, run };
}
