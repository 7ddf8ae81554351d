// PathView: the Path view keeps the selected body's whole path (the worker's pathLine of the engine's
// Timeline.path), follows the selection and edits, publishes what it shows, and draws nothing when
// off or when no body is selected.
import { Timeline } from "@chapgame/engine";
import { afterEach, describe, expect, it, vi } from "vitest";
import type { Editor } from "../editor";
import { PATH_MAX_POINTS, type PathLine, pathLine } from "../remote/pathLine";
import { createUiStore } from "../store/uiStore";
import { settled, testEditor } from "../testing/harness";
import { sceneOf } from "../testing/scenes";
import { COST_FACTOR, PathView } from "./pathView";

const scene = sceneOf(
  [
    { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [4, 0] },
    { time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 3 },
  ],
  0,
);

/** The engine's own line for body id of `sc` computed to `horizon`. */
function expected(id: string, horizon: number, sc = scene) {
  const tl = Timeline.fromScene(sc, { compute: false });
  tl.prolongTo(horizon);
  return pathLine(tl.path(id), PATH_MAX_POINTS);
}

const views: PathView[] = [];
afterEach(() => {
  for (const v of views.splice(0)) v.dispose();
});

async function setup() {
  const h = testEditor();
  await h.editor.loadScene(scene, { undoable: false });
  await settled(h.client);
  let redraws = 0;
  const view = new PathView(h.editor, () => redraws++);
  views.push(view);
  const until = async (check: () => boolean) => {
    for (let k = 0; k < 200 && !check(); k++) await new Promise((r) => setTimeout(r, 5));
    expect(check()).toBe(true);
  };
  return { ...h, view, until, redraws: () => redraws };
}

describe("PathView", () => {
  it("draws nothing until the view is on and a body is selected; then the engine's path of it", async () => {
    const { editor, client, view, until } = await setup();
    editor.ui.setState({ selection: { kind: "body", id: "a" } });
    await settled(client);
    expect(view.line).toBeNull();
    editor.ui.setState({ path: true });
    await until(() => view.line !== null);
    const horizon = client.getSnapshot().horizon;
    expect(view.line).toEqual(expected("a", horizon));
    expect(editor.ui.getState().pathShown).toEqual({ id: "a", cutAt: null });
    // a line or point selected: nothing
    editor.ui.setState({ selection: { kind: "line", id: "a" } });
    expect(view.line).toBeNull();
    expect(editor.ui.getState().pathShown).toBeNull();
  });

  it("follows the selection to another body, and an edit to the new history", async () => {
    const { editor, client, view, until } = await setup();
    editor.ui.setState({ path: true, selection: { kind: "body", id: "a" } });
    await until(() => view.line !== null);
    editor.ui.setState({ selection: { kind: "body", id: "b" } });
    expect(view.line).toBeNull(); // never the other body's path meanwhile
    await until(() => editor.ui.getState().pathShown?.id === "b");
    const horizon = client.getSnapshot().horizon;
    expect(view.line).toEqual(expected("b", horizon));
    const before = view.line;
    await editor.giveVelocity("b", [0, 1]); // at t = 0: b leaves upwards before a arrives
    await settled(client);
    await until(() => view.line !== before && view.line !== null);
    const edited = Timeline.fromScene(client.getSnapshot().doc!, { compute: false });
    edited.prolongTo(client.getSnapshot().horizon);
    await until(() => JSON.stringify(view.line) === JSON.stringify(pathLine(edited.path("b"))));
  });

  it("turned off, it forgets the path and says it shows none", async () => {
    const { editor, view, until } = await setup();
    editor.ui.setState({ path: true, selection: { kind: "body", id: "a" } });
    await until(() => view.line !== null);
    editor.ui.setState({ path: false });
    expect(view.line).toBeNull();
    expect(editor.ui.getState().pathShown).toBeNull();
  });

  it("a body the history does not hold (yet) gives no path, and no error", async () => {
    const { editor, client, view } = await setup();
    expect(await client.path("ghost", PATH_MAX_POINTS)).toBeNull(); // what the view is answered
    let answered = false;
    const ask = client.path.bind(client);
    client.path = (id, max) =>
      ask(id, max).finally(() => {
        answered = true;
      });
    editor.ui.setState({ path: true, selection: { kind: "body", id: "ghost" } });
    for (let k = 0; k < 200 && !answered; k++) await new Promise((r) => setTimeout(r, 5));
    expect(answered).toBe(true);
    await new Promise((r) => setTimeout(r, 0));
    expect(view.line).toBeNull();
    expect(editor.ui.getState().pathShown).toBeNull();
    expect(editor.ui.getState().message).toBeNull();
  });
});

describe("PathView while the history keeps changing", () => {
  it("spaces requests by at least COST_FACTOR times what the last one took (a slow worker is not flooded)", async () => {
    // a fake editor: the revision moves every 10 ms (a computation), each path takes 60 ms to come
    const ui = createUiStore({ path: true, selection: { kind: "body", id: "a" } });
    let revision = 1;
    const listeners = new Set<() => void>();
    const sent: number[] = [];
    const client = {
      getSnapshot: () => ({ revision }),
      subscribe: (l: () => void) => {
        listeners.add(l);
        return () => listeners.delete(l);
      },
      path: () => {
        sent.push(performance.now());
        return new Promise<PathLine>((r) =>
          setTimeout(() => r({ points: new Float64Array(4), cutAt: null }), 60),
        );
      },
    };
    // a fake clock (the timers and performance.now): real time made this test depend on the load
    // (review of session 20); now the spacing is exact
    vi.useFakeTimers({ toFake: ["setTimeout", "clearTimeout", "performance"] });
    try {
      const view = new PathView({ ui, client } as unknown as Editor, () => {});
      views.push(view);
      for (let ms = 0; ms < 1500; ms += 10) {
        revision++;
        for (const l of listeners) l();
        await vi.advanceTimersByTimeAsync(10);
      }
    } finally {
      vi.useRealTimers();
    }
    // REFRESH_MS alone would allow a request every 400 ms; 60 ms each makes it every 600 ms
    for (let k = 1; k < sent.length; k++) expect(sent[k]! - sent[k - 1]!).toBe(COST_FACTOR * 60);
    // at 0, 600 and 1200 ms
    expect(sent.length).toBe(3);
  });
});
