/**
 * Test harness: an Editor whose TimelineHost runs in-process over a port pair (the same protocol as
 * the Web Worker, delivered asynchronously), with the engine's real Timeline.
 */
import { newtonsCradle, Timeline } from "@chapgame/engine";
import { Editor } from "../editor";
import type { SceneFile, Until } from "../engineTypes";
import { TimelineClient } from "../remote/client";
import { TimelineHost } from "../remote/host";
import { portPair } from "../remote/localPort";
import type { Port, RequestMessage } from "../remote/protocol";
import type { TimelineLike } from "../remote/timelineLike";
import { createUiStore } from "../store/uiStore";

/**
 * Options of a test host. `slow`: each slice computes at most one event and each reading of the
 * host's clock takes 3 ms, so a round of slices (ROUND_MS = 8) computes one event: the check of an edit
 * in the past lasts many rounds (requests sent meanwhile meet it).
 */
export interface HostOptions {
  slow?: boolean;
}

/** A host in-process behind a fresh port pair; `host.handle` may be replaced to simulate a hang. */
export function hostPort(options: HostOptions = {}): { port: Port; host: TimelineHost } {
  const [main, worker] = portPair();
  let clock = 0;
  const timeline = (scene: SceneFile): TimelineLike => {
    const tl = Timeline.fromScene(scene, { compute: false });
    if (!options.slow) return tl;
    const slice = tl.prolongSlice.bind(tl);
    return Object.assign(tl, { prolongSlice: (u: Until, _budget: number) => slice(u, 1) });
  };
  const host = new TimelineHost(
    timeline,
    {
      post: (m) => worker.postMessage(m),
      schedule: (fn) => setTimeout(fn, 0),
      now: options.slow ? () => (clock += 3) : () => performance.now(),
    },
    { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions: [] },
  );
  worker.onmessage = (e) => host.handle(e.data as RequestMessage);
  return { port: main, host };
}

export function testEditor(options: HostOptions = {}): {
  editor: Editor;
  client: TimelineClient;
  host: TimelineHost;
} {
  const { port, host } = hostPort(options);
  const client = new TimelineClient(port);
  const editor = new Editor(client, createUiStore());
  editor.portFactory = () => hostPort(options).port;
  return { editor, client, host };
}

/** A test editor with Newton's cradle loaded (not undoable) and its computation settled. */
export async function cradleEditor(): Promise<ReturnType<typeof testEditor>> {
  return sceneEditor(newtonsCradle());
}

/** A test editor with `scene` loaded (not undoable; a refusal fails the test) and its computation settled. */
export async function sceneEditor(scene: SceneFile): Promise<ReturnType<typeof testEditor>> {
  const h = testEditor();
  const refused = await h.editor.loadScene(scene, { undoable: false });
  if (refused !== null) throw new Error(`the test scene was refused: ${refused}`);
  await settled(h.client);
  return h;
}

/**
 * Resolves when the host has no computation running and no request of the client waits for an
 * answer (after a load, edit or compute; an edit in the past is answered only after a check).
 */
export async function settled(client: TimelineClient, timeoutMs = 10_000): Promise<void> {
  const end = Date.now() + timeoutMs;
  await new Promise((r) => setTimeout(r, 0));
  while (client.getSnapshot().computing !== null || client.getSnapshot().revision < 0 || client.waiting > 0) {
    if (Date.now() > end) throw new Error("host did not settle");
    await new Promise((r) => setTimeout(r, 5));
  }
  await new Promise((r) => setTimeout(r, 5));
}
