/**
 * The Web Worker entry: a TimelineHost over the engine's Timeline, bound to the worker's port.
 * Timelines are built with `compute: false`: loading a scene only schedules its actions (their
 * `until`s are not run inside the load), and the host computes ahead in slices it can report and
 * cancel.
 */
import { Timeline } from "@chapgame/engine";
import type { SceneFile } from "../engineTypes";
import { TimelineHost } from "./host";
import type { HostMessage, RequestMessage } from "./protocol";

const empty: SceneFile = { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions: [] };
const channel = new MessageChannel();
const tasks: (() => void)[] = [];
channel.port1.onmessage = () => tasks.shift()?.();

const host = new TimelineHost(
  (scene) => Timeline.fromScene(scene, { compute: false }),
  {
    post: (m: HostMessage, transfer?: Transferable[]) => self.postMessage(m, { transfer: transfer ?? [] }),
    schedule: (fn) => {
      tasks.push(fn);
      channel.port2.postMessage(null);
    },
    now: () => performance.now(),
  },
  empty,
);

self.onmessage = (e: MessageEvent<RequestMessage>) => host.handle(e.data);
