// Random short sequences of edits, Undo, Redo and Cancel over a slow host (an edit in the past is
// checked over many rounds, so an Undo, a Redo or a Cancel asked after it meets it queued, during
// its check or after), also two or three edits asked together with Undos and Redos bound to them,
// compared with the Undo/Redo a user expects (testing/undoModel.ts). After
// each step: the scene holds exactly the surviving edits, every Redo entry is the scene redoing it
// must give (no edit made obsolete by a newer edit comes back), and Redo holds no more entries than
// steps were undone. The seed is printed; UNDO_SEED=<n> replays one.
import { describe, expect, it } from "vitest";
import { canRedo } from "./doc/undoIntents";
import type { Action, SceneFile } from "./engineTypes";
import { UNDONE_DURING_CHECK } from "./remote/protocol";
import { settled, testEditor } from "./testing/harness";
import { boxScene } from "./testing/scenes";
import {
  askedTogether,
  emptyModel,
  made,
  type Outcome,
  redone,
  takenBack,
  type UndoModel,
  undone,
} from "./testing/undoModel";

const addE: Action = { time: 30, type: "addBody", id: "e", x: 50, y: 50, r: 1, m: 1 };
const base: SceneFile = boxScene([addE]);

/**
 * Edit `4k + j` (the j-th of the edits step k asks, j < 4): a velocity given at its own time before
 * e's addition, or (one in four) a disc on e's place.
 */
function editOf(e: number): Action {
  const k = Math.floor(e / 4);
  const j = e % 4;
  const time = 2 + k * 0.37 + j * 0.09;
  if ((k + j) % 4 === 3) return { time, type: "addBody", id: `z${k}_${j}`, x: 50, y: 50.5, r: 1, m: 1 };
  return { time, type: "giveVelocity", id: "abcd"[(k + j) % 4] as string, v: [(k % 5) - 2, 1] };
}

/** An action as the sequences tell them apart (each edit has its own time). */
const key = (a: Action): string => `${a.time}:${a.type}:${"id" in a ? a.id : ""}`;
const keys = (s: SceneFile): string[] => s.actions.map(key).sort();
const expected = (edits: readonly number[]): string[] =>
  [...base.actions, ...edits.map(editOf)].map(key).sort();

/** mulberry32: a small seeded generator. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

type Harness = ReturnType<typeof testEditor>;
type Model = UndoModel<number>;
const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

/** Resolves once the host shows a changed scene (an edit's check runs) or `edit` is answered. */
function checkingOr(h: Harness, edit: Promise<unknown>): Promise<unknown> {
  const rev = h.client.getSnapshot().docRevision;
  return Promise.race([
    edit,
    new Promise<void>((resolve) => {
      const stop = h.client.subscribe(() => {
        if (h.client.getSnapshot().docRevision === rev) return;
        stop();
        resolve();
      });
    }),
  ]);
}

/** Waits as a random step says before its Undo: not at all, until the check runs, or a few ms more. */
async function wait(h: Harness, edit: Promise<unknown>, rnd: () => number): Promise<string> {
  const r = rnd();
  if (r < 0.25) return "at once";
  await checkingOr(h, edit);
  if (r < 0.6) return "during the check";
  const ms = Math.floor(rnd() * 60);
  await sleep(ms);
  return `${ms} ms into the check`;
}

/** Whether a change asked is still queued or running (an Undo asked now is bound to it). */
const inFlight = (h: Harness): boolean => h.editor.intents.getState().past.length > 0;

const has = (h: Harness, k: number) =>
  h.client.getSnapshot().doc!.actions.some((a) => key(a) === key(editOf(k)));

/**
 * What a step did (for the failure message), the model after it, and the steps undone since the
 * last edit made after it (from `n` before it).
 */
interface Step {
  what: string;
  model: Model;
  undone: (n: number) => number;
}

/**
 * One random step (the k-th): an edit, alone or with an Undo (and a Redo) or a Cancel at a random
 * moment; edits asked together with Undos and Redos; Undo; Redo.
 */
async function step(h: Harness, m: Model, k: number, rnd: () => number): Promise<Step> {
  const next = 4 * k;
  const r = rnd();
  const e = h.editor;
  const same = (n: number) => n;
  if (r < 0.2) {
    const res = await e.edit([editOf(next)]);
    if (res !== null) return { what: `edit ${next}: ${res}`, model: m, undone: same };
    return { what: `edit ${next}: made`, model: made(m, next), undone: () => 0 };
  }
  if (r < 0.45) {
    const edit = e.edit([editOf(next)]);
    const when = await wait(h, edit, rnd);
    const bound = inFlight(h); // else the edit was answered first: the Undo is a plain one
    const [res] = await Promise.all([edit, e.undo()]);
    const what = `edit ${next}, Undo ${when}: `;
    if (res === null) return { what: `${what}made, undone`, model: undone(made(m, next)), undone: () => 1 };
    if (res === UNDONE_DURING_CHECK)
      return { what: `${what}taken back`, model: takenBack(m, next), undone: () => 1 };
    if (bound) return { what: `${what}${res}`, model: m, undone: same };
    const plain = (n: number) => (m.past.length > 0 ? n + 1 : n);
    return { what: `${what}${res}, then Undo`, model: undone(m), undone: plain };
  }
  if (r < 0.55) {
    const edit = e.edit([editOf(next)]);
    const when = await wait(h, edit, rnd);
    const bound = inFlight(h);
    const [res] = await Promise.all([edit, e.undo(), e.redo()]);
    const what = `edit ${next}, Undo and Redo ${when}: `;
    if (res === null) return { what: `${what}made`, model: made(m, next), undone: () => 0 };
    // Refused: the Undo bound to it or, asked after, to the last edit; Redo brings back what Undo took.
    if (res !== UNDONE_DURING_CHECK)
      return { what: `${what}${res}${bound ? "" : " (answered first)"}`, model: m, undone: same };
    await settled(h.client);
    const back = has(h, next);
    const model = redone(takenBack(m, next), !back);
    return { what: `${what}taken back, ${back ? "redone" : "refused"}`, model, undone: () => 0 };
  }
  if (r < 0.68) return together(h, m, next, rnd);
  if (r < 0.75) {
    const edit = e.edit([editOf(next)]);
    await checkingOr(h, edit);
    e.cancelCompute();
    const res = await edit;
    await settled(h.client);
    await e.goTo(20); // Cancel may also have stopped the computing ahead
    if (res !== null) return { what: `edit ${next}, Cancel: ${res}`, model: m, undone: same };
    return { what: `edit ${next}, Cancel: made`, model: made(m, next), undone: () => 0 };
  }
  if (r < 0.87) {
    await e.undo();
    return { what: "Undo", model: undone(m), undone: (n) => (m.past.length > 0 ? n + 1 : n) };
  }
  const first = m.future[0];
  await e.redo();
  await settled(h.client);
  const refused = first !== undefined && !has(h, first.edit);
  return {
    what: `Redo${refused ? " (refused)" : ""}`,
    model: redone(m, refused),
    undone: (n) => (first !== undefined ? n - 1 : n),
  };
}

/**
 * Two or three edits (`first`, `first + 1`...) asked one after another, then, at a random moment,
 * Undos (up to one more than the edits) and Redos (up to as many) asked at once: while the edits are
 * in flight they are bound to them (the last edit first). Taking an edit back with a later one
 * queued behind it lost it from Redo (review of session 16).
 */
async function together(h: Harness, m: Model, first: number, rnd: () => number): Promise<Step> {
  const e = h.editor;
  const n = 2 + Math.floor(rnd() * 2);
  const ids = Array.from({ length: n }, (_, j) => first + j);
  const asked = ids.map((id) => e.edit([editOf(id)]));
  const when = await wait(h, asked[0] as Promise<unknown>, rnd);
  const undos = Math.floor(rnd() * (n + 2));
  const redos = Math.floor(rnd() * (undos + 1));
  const bound = inFlight(h); // else all were answered first: the Undos are plain ones
  const moves = [
    ...Array.from({ length: undos }, () => e.undo()),
    ...Array.from({ length: redos }, () => e.redo()),
  ];
  const res = await Promise.all(asked);
  await Promise.all(moves);
  await settled(h.client);
  const outcome = (x: string | null): Outcome =>
    x === null ? "made" : x === UNDONE_DURING_CHECK ? "takenBack" : "refused";
  const edits = ids.map((id, j) => [id, outcome(res[j] ?? null)] as const);
  const refused = (edit: number) => !has(h, edit);
  const model = bound
    ? askedTogether(m, edits, undos, redos, refused)
    : askedTogether(askedTogether(m, edits, 0, 0, refused), [], undos, redos, refused);
  const what = `edits ${ids.join(", ")} (${edits.map(([, o]) => o).join(", ")}), ${undos} Undo, ${redos} Redo ${when}${bound ? "" : " (answered first)"}`;
  const reset = edits.some(([, o]) => o !== "refused");
  const grown = model.future.length - m.future.length;
  return { what, model, undone: (u) => (reset ? model.future.length : u + grown) };
}

/** The editor's scene and history against the model's. */
function check(h: Harness, m: Model, undoneSteps: number): void {
  const hist = h.editor.history.getState();
  expect(keys(h.client.getSnapshot().doc!)).toEqual(expected(m.past));
  expect(hist.past.map(keys)).toEqual(m.past.map((_, i) => expected(m.past.slice(0, i))));
  const redoable = m.future.map((_, i) =>
    expected([...m.past, ...m.future.slice(0, i + 1).map((f) => f.edit)]),
  );
  expect(hist.future.map(keys)).toEqual(redoable);
  expect(hist.future.length).toBeLessThanOrEqual(undoneSteps);
  expect(h.editor.intents.getState()).toMatchObject({ past: [], future: [] });
  expect(canRedo(h.editor.intents.getState(), hist.future.length)).toBe(m.future.length > 0);
}

describe("Undo, Redo and Cancel in random sequences around edits' checks", () => {
  it("keep the scene and Redo as the user expects", { timeout: 120_000 }, async () => {
    const seed = Number(process.env.UNDO_SEED ?? Math.floor(Math.random() * 2 ** 31));
    console.log(`editorUndoSequences seed ${seed} (replay: UNDO_SEED=${seed})`);
    const rnd = random(seed);
    for (let run = 0; run < 8; run++) {
      const h = testEditor({ slow: true });
      await h.editor.loadScene(base, { undoable: false });
      await settled(h.client);
      await h.editor.goTo(20);
      await settled(h.client);
      let m: Model = emptyModel();
      let undoneSteps = 0; // steps undone since the last edit made, less those redone
      const steps: string[] = [];
      for (let next = 0; next < 10; next++) {
        try {
          // The model throws when the editor did what the contract rules out (told in the message).
          const done = await step(h, m, run * 10 + next, rnd);
          await settled(h.client);
          steps.push(done.what);
          m = done.model;
          undoneSteps = done.undone(undoneSteps);
          check(h, m, undoneSteps);
        } catch (err) {
          throw new Error(
            `seed ${seed}, run ${run}, after: ${steps.join(" / ") || "(its first step)"}\n${(err as Error).message}`,
          );
        }
      }
    }
  });
});
