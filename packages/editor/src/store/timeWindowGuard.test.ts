import { describe, expect, it } from "vitest";
import type { ComputeStatus } from "../remote/protocol";
import { cradleEditor, settled } from "../testing/harness";
import { loneDiscScene } from "../testing/scenes";
import { createStore } from "./createStore";
import { historyEnd, keepTimeWindow } from "./timeWindowGuard";
import { createUiStore } from "./uiStore";

const restoring = (targetTime: number): ComputeStatus => ({
  events: 0,
  targetEvents: null,
  targetTime,
  startHorizon: 0,
  restore: true,
});

function guarded(horizon: number) {
  const info = createStore({
    horizon,
    computing: null as ComputeStatus | null,
    idle: false,
    stopped: null as string | null,
  });
  const source = { getSnapshot: () => info.getState(), subscribe: (l: () => void) => info.subscribe(l) };
  const ui = createUiStore({ t: 15, timeWindow: { lo: 10, hi: 20 } });
  keepTimeWindow(ui, source);
  return { info, ui };
}

describe("time window guard", () => {
  it("the window turns page by page as the time runs on, and jumps to a far time", () => {
    const { ui } = guarded(100);
    ui.setState({ t: 19.5 });
    expect(ui.getState().timeWindow).toEqual({ lo: 10, hi: 20 });
    ui.setState({ t: 20.25 }); // playing past hi
    expect(ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    ui.setState({ t: 19 }); // playing backwards
    expect(ui.getState().timeWindow).toEqual({ lo: 10, hi: 20 });
    ui.setState({ t: 85 }); // a typed time
    expect(ui.getState().timeWindow).toEqual({ lo: 80, hi: 90 });
    // the whole history stays the whole history
    ui.setState({ timeWindow: null, t: 3 });
    expect(ui.getState().timeWindow).toBeNull();
  });

  it("playing into the computation turns whole pages; paused, or with nothing more to compute, they stay inside the history", () => {
    const { info, ui } = guarded(22);
    ui.setState({ playing: true, speed: 1, t: 20.5 });
    // the next page, though the history ends at 22 (shifted back to [12, 22] it crept 2 s at a time)
    expect(ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    // the horizon catches up: the same page
    info.setState({ horizon: 26 });
    ui.setState({ t: 25 });
    expect(ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    // backwards, or with auto-extend off, or no event left: shifted inside the history
    ui.setState({ timeWindow: { lo: 10, hi: 20 }, t: 15, speed: -1 });
    ui.setState({ t: 20.5 });
    expect(ui.getState().timeWindow).toEqual({ lo: 16, hi: 26 });
    ui.setState({
      timeWindow: { lo: 10, hi: 20 },
      t: 15,
      speed: 1,
      calc: { ...ui.getState().calc, autoExtend: false },
    });
    ui.setState({ t: 20.5 });
    expect(ui.getState().timeWindow).toEqual({ lo: 16, hi: 26 });
    ui.setState({ timeWindow: { lo: 10, hi: 20 }, t: 15, calc: { ...ui.getState().calc, autoExtend: true } });
    info.setState({ idle: true });
    ui.setState({ t: 20.5 });
    expect(ui.getState().timeWindow).toEqual({ lo: 16, hi: 26 });
    // paused, a running computation grows the history too
    ui.setState({ timeWindow: { lo: 10, hi: 20 }, t: 15, playing: false });
    info.setState({
      idle: false,
      computing: { events: 0, targetEvents: null, targetTime: 100, startHorizon: 22, restore: false },
    });
    ui.setState({ t: 20.5 });
    expect(ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
  });

  it("a page turned into the computation settles inside the history once it stops growing, the time kept", () => {
    const computing = (targetTime: number): ComputeStatus => ({ ...restoring(targetTime), restore: false });
    // the computation stops short of the page's end
    const a = guarded(22);
    a.ui.setState({ playing: true, speed: 1, t: 20.5 });
    expect(a.ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    a.info.setState({ horizon: 23, idle: true }); // no event left: playing asks for nothing more
    expect(a.ui.getState().timeWindow).toEqual({ lo: 13, hi: 23 });
    expect(a.ui.getState().t).toBe(20.5);
    // a pause does not settle it (playing on grows the history: pressing the thumb pauses), turning
    // auto-extend off does
    const b = guarded(22);
    b.ui.setState({ playing: true, speed: 1, t: 21 });
    expect(b.ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    b.ui.setState({ playing: false });
    expect(b.ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    b.ui.setState({ calc: { ...b.ui.getState().calc, autoExtend: false } });
    expect(b.ui.getState().timeWindow).toEqual({ lo: 12, hi: 22 });
    // paused while a computation runs: once it ends with nothing left, or the engine stopped
    const c = guarded(22);
    c.info.setState({ computing: computing(40) });
    c.ui.setState({ t: 21 });
    expect(c.ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    c.info.setState({ horizon: 25 });
    expect(c.ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    c.info.setState({ horizon: 27, computing: null, stopped: "Zeno state" });
    expect(c.ui.getState().timeWindow).toEqual({ lo: 17, hi: 27 });
    expect(c.ui.getState().t).toBe(21);
    // a history cut by an edit in the past while computing ahead: the window waits for it (also
    // with auto-extend off, the computation's end then being the end of the growth)
    const d = guarded(22);
    d.ui.setState({ calc: { ...d.ui.getState().calc, autoExtend: false } });
    d.info.setState({ computing: computing(40) });
    d.ui.setState({ t: 21 });
    d.info.setState({ horizon: 21, computing: null });
    expect(d.ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
  });

  it("an undo keeps the window: the time is held past the horizon, then a restore brings the history back", () => {
    const { info, ui } = guarded(100);
    // the horizon drops to 0 before the restore starts (two messages)
    info.setState({ horizon: 0, computing: null });
    expect(ui.getState().timeWindow).toEqual({ lo: 10, hi: 20 });
    info.setState({ horizon: 4, computing: restoring(100) });
    expect(historyEnd(info.getState())).toBe(100);
    expect(historyEnd(info.getState(), 150)).toBe(150);
    // pages turned during the restore may reach past the horizon, up to where the restore goes
    ui.setState({ t: 21 });
    expect(ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    info.setState({ horizon: 100, computing: null });
    expect(ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    // a history that ends before the window once the time is back in it: the whole history
    info.setState({ horizon: 13, computing: null });
    expect(ui.getState().timeWindow).toEqual({ lo: 20, hi: 30 });
    ui.setState({ t: 13 });
    expect(ui.getState().timeWindow).toBeNull();
  });

  it("in an editor: an undo keeps the zoom, the load of another scene returns to the whole history", async () => {
    const { editor, client } = await cradleEditor();
    expect(client.getSnapshot().horizon).toBe(10);
    editor.setTime(7);
    editor.ui.setState({ timeWindow: { lo: 6, hi: 8 } });
    // an edit in the past and its undo recompute the history after it
    expect(await editor.updateBody("striker", { v: [8, 0] })).toBeNull();
    await settled(client);
    await editor.undo();
    await settled(client);
    expect(editor.ui.getState().t).toBe(7);
    expect(editor.ui.getState().timeWindow).toEqual({ lo: 6, hi: 8 });
    // a time typed past the horizon is computed and shown in a window of the same span, inside
    // the history (which ends there)
    await editor.goTo(25);
    expect(editor.ui.getState().t).toBe(25);
    expect(client.getSnapshot().horizon).toBe(25);
    expect(editor.ui.getState().timeWindow).toEqual({ lo: 23, hi: 25 });
    // an edit in the past cuts the history inside the window: the window stays
    editor.setTime(24.5);
    expect(await editor.updateBody("striker", { v: [8, 0] })).toBeNull();
    await settled(client);
    expect(editor.ui.getState().timeWindow).toEqual({ lo: 23, hi: 25 });
    await editor.loadScene(loneDiscScene());
    expect(editor.ui.getState().timeWindow).toBeNull();
    await settled(client);
    expect(editor.ui.getState().timeWindow).toBeNull();
  });

  it("a load of another scene returns to the whole history, also from a window at its start", async () => {
    const { editor, client } = await cradleEditor();
    editor.ui.setState({ timeWindow: { lo: 0, hi: 2.5 } });
    await editor.loadScene(loneDiscScene());
    expect(editor.ui.getState().timeWindow).toBeNull();
    await settled(client);
    expect(editor.ui.getState().timeWindow).toBeNull();
    // a reload that keeps the time (a rename, a rewrite) keeps the zoom
    editor.ui.setState({ timeWindow: { lo: 0, hi: 2.5 } });
    expect(await editor.rename("body", "lonely", "solo")).toBeNull();
    await settled(client);
    expect(editor.ui.getState().timeWindow).toEqual({ lo: 0, hi: 2.5 });
  });
});
