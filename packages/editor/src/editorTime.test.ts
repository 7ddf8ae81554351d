// EditorTime over the worker protocol: event steps (chained, computing ahead past the horizon),
// going to a typed time whose computation is cancelled, and a Play that cannot start.
import { bouncingBalls } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import type { Action } from "./engineTypes";
import type { RequestMessage } from "./remote/protocol";
import { settled, testEditor } from "./testing/harness";
import { sceneOf } from "./testing/scenes";

/** An editor with `actions` loaded and computed ahead by the default settings (10 s). */
async function loaded(actions: Action[]) {
  const h = testEditor();
  expect(await h.editor.loadScene(sceneOf(actions), { undoable: false })).toBeNull();
  await settled(h.client);
  return h;
}

/** a (v = 1) meets b at t = 20, past the 10 s computed after loading; then only b moves, for ever. */
const farMeeting: Action[] = [
  { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
  { time: 0, type: "addBody", id: "b", x: 22, y: 0, r: 1, m: 1 },
];

/** Keeps the host's computation from progressing (it runs until cancelled); returns the undo. */
function stall(host: unknown): () => void {
  const h = host as { round(): void };
  const round = h.round;
  h.round = () => {};
  return () => {
    h.round = round;
  };
}

/** Resolves once the host reports a computation running. */
async function computing(client: ReturnType<typeof testEditor>["client"]): Promise<void> {
  const end = Date.now() + 5000;
  while (client.getSnapshot().computing === null) {
    if (Date.now() > end) throw new Error("no computation started");
    await new Promise((r) => setTimeout(r, 1));
  }
}

describe("EditorTime.setTime while the history is computed again", () => {
  it("a time dragged past the recomputation's progress, inside the history the user had, is held there", async () => {
    // Audit of session 16: the slider spans the whole history during an undo's recomputation,
    // but a time dragged past its progress jumped back to it.
    const h = await loaded(farMeeting);
    expect(h.client.getSnapshot().horizon).toBe(10);
    h.editor.setTime(2);
    const resume = stall(h.host);
    expect(await h.editor.edit([{ time: 2, type: "giveVelocity", id: "b", v: [0.1, 0] }])).toBeNull();
    await computing(h.client);
    expect(h.client.getSnapshot().horizon).toBe(2);
    h.editor.setTime(8);
    expect(h.editor.ui.getState().t).toBe(8);
    // the editor's compute-ahead (10 s from the edit) took the recomputation over: up to t = 12
    expect(h.client.getSnapshot().computing).toMatchObject({ restore: true, targetTime: 12 });
    h.editor.setTime(50); // past the end of the computation running: its end
    expect(h.editor.ui.getState().t).toBe(12);
    h.editor.setTime(8);
    resume();
    (h.host as unknown as { kick(): void }).kick();
    await settled(h.client);
    expect(h.client.getSnapshot().horizon).toBeGreaterThanOrEqual(10);
    expect(h.editor.ui.getState().t).toBe(8);
  });
});

describe("EditorTime event steps", () => {
  it("quick presses of → each step one event, from where the previous step landed", async () => {
    // Each step read the current time before the previous step's reply had moved it: five quick
    // presses stepped one event.
    const h = testEditor();
    await h.editor.loadScene(bouncingBalls(), { undoable: false });
    await settled(h.client);
    const times: number[] = [];
    while (times.length < 5) times.push((await h.client.nextEvent(times.at(-1) ?? 0))!);
    await Promise.all([1, 2, 3, 4, 5].map(() => h.editor.stepEvent(1)));
    expect(h.editor.ui.getState().t).toBe(times[4]);
    await Promise.all([1, 2].map(() => h.editor.stepEvent(-1)));
    expect(h.editor.ui.getState().t).toBe(times[2]);
  });

  it("a step waiting behind another starts from where the user moved the time meanwhile", async () => {
    const h = testEditor();
    await h.editor.loadScene(bouncingBalls(), { undoable: false });
    await settled(h.client);
    const first = (await h.client.nextEvent(3))!;
    const second = (await h.client.nextEvent(first))!;
    const handle = h.host.handle.bind(h.host);
    h.host.handle = (m: RequestMessage) => {
      if (m.op === "nextEvent") setTimeout(() => handle(m), 20);
      else handle(m);
    };
    const steps = [h.editor.stepEvent(1)];
    await new Promise((r) => setTimeout(r, 5)); // the first step waits for its reply
    h.editor.setTime(3); // the user scrubs: that step lands nowhere, the next ones start from 3
    steps.push(h.editor.stepEvent(1), h.editor.stepEvent(1));
    await Promise.all(steps);
    expect(h.editor.ui.getState().t).toBe(second);
  });

  it("→ past the computed history computes ahead to the next event and steps there", async () => {
    // It said "No event after t = … up to the computed horizon (10 s)" although a body stopped at 100.
    const h = await loaded(farMeeting);
    expect(h.client.getSnapshot().horizon).toBe(10);
    h.editor.setTime(1);
    await h.editor.stepEvent(1);
    expect(h.editor.ui.getState().t).toBe(20);
    expect(h.editor.ui.getState().message).toBeNull();
    // After it nothing more happens (b moves on for ever): said so, the time stays.
    await h.editor.stepEvent(1);
    await settled(h.client);
    expect(h.client.getSnapshot().idle).toBe(true);
    expect(h.editor.ui.getState().t).toBe(20);
    expect(h.editor.ui.getState().message).toEqual({
      text: "No event after t = 20 s: nothing more happens in this scene.",
      tone: "info",
    });
  });

  it("→ from a time past the computed history first computes up to that time in one request", async () => {
    // after an undo's recomputation was cancelled short of the time: one event per request took
    // about an hour to cover 20 s of a 20,000-disc gas (audit of session 15)
    const h = await loaded(farMeeting);
    const asked: RequestMessage[] = [];
    const handle = h.host.handle.bind(h.host);
    h.host.handle = (m: RequestMessage) => {
      if (m.op === "compute") asked.push(m);
      handle(m);
    };
    h.editor.ui.setState({ t: 15 }); // what a reload at t = 15 leaves, its recomputation cancelled
    h.editor.info("No event before t = 0 s."); // an earlier step's notice: a successful step clears it
    await h.editor.stepEvent(1);
    expect(h.editor.ui.getState().t).toBe(20);
    expect(h.editor.ui.getState().message).toBeNull();
    expect(asked[0]).toMatchObject({ until: { time: 5 } });
    expect(asked.length).toBeLessThanOrEqual(3);
  });

  it("computing ahead to the next event can be cancelled: the step says so and stays", async () => {
    const h = await loaded(farMeeting);
    h.editor.setTime(1);
    const resume = stall(h.host);
    const step = h.editor.stepEvent(1);
    await computing(h.client);
    expect(h.client.getSnapshot().computing?.targetEvents).toBe(1);
    h.editor.cancelCompute();
    await step;
    resume();
    expect(h.editor.ui.getState().t).toBe(1);
    expect(h.editor.ui.getState().message).toEqual({
      text: "No event after t = 1 s up to t = 10 s: the computation was cancelled.",
      tone: "info",
    });
  });

  it("a step asked while a computation runs waits for it, then steps to the next event", async () => {
    const h = await loaded(farMeeting);
    h.editor.setTime(1);
    const resume = stall(h.host);
    void h.editor.computeAhead(); // 10 s more: still no event before 20
    await computing(h.client);
    const step = h.editor.stepEvent(1);
    await new Promise((r) => setTimeout(r, 20));
    resume();
    (h.host as unknown as { kick(): void }).kick();
    await step;
    expect(h.editor.ui.getState().t).toBe(20);
  });
});

describe("EditorTime typed times and Play", () => {
  it("a typed time whose computation is cancelled shows the end of the history and says so", async () => {
    const h = testEditor();
    await h.editor.loadScene(bouncingBalls(), { undoable: false });
    await settled(h.client);
    const going = h.editor.goTo(1e6);
    await computing(h.client);
    h.editor.cancelCompute();
    await going;
    const horizon = h.client.getSnapshot().horizon;
    expect(horizon).toBeLessThan(1e6);
    expect(h.editor.ui.getState().t).toBe(horizon);
    expect(h.editor.ui.getState().message).toEqual({
      text: `Computation cancelled at t = ${Number(horizon.toPrecision(6))} s; showing the end of the computed history.`,
      tone: "info",
    });
  });

  it("Play backwards from t = 0 says why nothing plays; forwards, or from a later time, it plays", async () => {
    const h = await loaded(farMeeting);
    h.editor.setSpeed(-1);
    h.editor.togglePlay();
    expect(h.editor.ui.getState().playing).toBe(false);
    expect(h.editor.ui.getState().message).toEqual({
      text: "Playing backwards from t = 0: nothing before it. Set a positive speed to play forwards.",
      tone: "info",
    });
    h.editor.setTime(2);
    h.editor.togglePlay();
    expect(h.editor.ui.getState().playing).toBe(true);
    h.editor.togglePlay();
    h.editor.setTime(0);
    h.editor.setSpeed(1);
    h.editor.togglePlay();
    expect(h.editor.ui.getState().playing).toBe(true);
  });

  it("why playback did not start goes once it starts (1× after Reverse at t = 0) or the speed changes", async () => {
    const h = await loaded(farMeeting);
    h.editor.setSpeed(-1);
    h.editor.play();
    expect(h.editor.ui.getState().message?.text).toMatch(/^Playing backwards from t = 0/);
    h.editor.setSpeed(1);
    expect(h.editor.ui.getState().message).toBeNull(); // its advice was followed
    h.editor.setSpeed(-1);
    h.editor.play();
    h.editor.ui.setState({ speed: 1 }); // the store alone: only the start removes it
    h.editor.play();
    expect(h.editor.ui.getState()).toMatchObject({ playing: true, message: null });
  });

  it("a message of someone else stays when playback starts", async () => {
    const h = await loaded(farMeeting);
    h.editor.ui.setState({ message: { text: "Saved.", tone: "info" } });
    h.editor.play();
    expect(h.editor.ui.getState().message?.text).toBe("Saved.");
  });

  it("speed 0: Play says nothing would move and does not start; setting 0 while playing pauses and says so", async () => {
    const h = await loaded(farMeeting);
    h.editor.setSpeed(0);
    h.editor.togglePlay();
    expect(h.editor.ui.getState().playing).toBe(false);
    expect(h.editor.ui.getState().message?.text).toBe(
      "Speed 0: nothing would move. Set a speed (Speed field, 1×) to play.",
    );
    h.editor.setSpeed(0.5);
    expect(h.editor.ui.getState().message).toBeNull();
    h.editor.togglePlay();
    expect(h.editor.ui.getState().playing).toBe(true);
    h.editor.setSpeed(0.0004); // kept to 0.001: 0
    expect(h.editor.ui.getState()).toMatchObject({ speed: 0, playing: false });
    expect(h.editor.ui.getState().message?.text).toBe(
      "Speed 0: paused. Set a speed (Speed field, 1×) to play again.",
    );
  });

  it("Play forwards at the end of the history with nothing to compute says why; with auto-extend it plays", async () => {
    const h = await loaded(farMeeting);
    const end = h.client.getSnapshot().horizon;
    h.editor.ui.setState((s) => ({ t: end, calc: { ...s.calc, autoExtend: false } }));
    h.editor.togglePlay();
    expect(h.editor.ui.getState().playing).toBe(false);
    expect(h.editor.ui.getState().message).toEqual({
      text: `At the end of the computed history (t = ${Number(end.toPrecision(6))} s): auto-extend is off (Calculation panel).`,
      tone: "info",
    });
    h.editor.ui.setState((s) => ({ calc: { ...s.calc, autoExtend: true } }));
    h.editor.togglePlay();
    expect(h.editor.ui.getState().playing).toBe(true);
  });
});
