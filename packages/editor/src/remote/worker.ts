/** The Web Worker entry: a TimelineHost over the engine's Timeline, bound to the worker's port. */
import type { SceneFile } from "../engineTypes";
import { fakeTimeline } from "./fakeTimeline";
import { TimelineHost } from "./host";
import type { HostMessage, RequestMessage } from "./protocol";

const empty: SceneFile = { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions: [] };
const channel = new MessageChannel();
const tasks: (() => void)[] = [];
channel.port1.onmessage = () => tasks.shift()?.();

const host = new TimelineHost(
  fakeTimeline,
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
