/**
 * End-to-end, in Debian's Chromium: every edit says what it changed and how to undo it, as adds and
 * deletes do ("Added disc …"). A Move drag, a Velocity drag, a Cue strike and a table cell said
 * nothing. Each now gives one message (a drag one at its release, none while the pointer moves),
 * with the new values and what Undo restores (doc/editConfirm.ts), and the message moves neither
 * the stage nor its canvas (the message bar is a slot of the header one line high), in a wide
 * window and in a short one (700 × 420, where a long message is cut to its line with More).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { sceneFile } from "./editorScenes.js";
import { stageBoxes } from "./stageProbes.js";
import { withWindowSize } from "./windowSize.js";

const editor = editorForFile();

type PageEditor = {
  ui: {
    getState(): { view: { cx: number; cy: number; scale: number }; message: { text: string } | null };
    setState(patch: object): void;
    subscribe(fn: (s: { message: { text: string } | null }, p: { message: unknown }) => void): () => void;
  };
  loadScene(scene: unknown, options?: object): Promise<string | null>;
};
type Recorder = { chapgame: PageEditor; __messages: string[]; __unsubscribe?: () => void };

/** Discs a and b of radius 1 at rest at (0, 0) and (10, 0). */
const SCENE = sceneFile([
  { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] },
  { time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] },
]);

/** Loads SCENE (fitted) and starts recording every message shown from then on. */
async function fresh(): Promise<void> {
  await editor.page.evaluate(async (sc) => {
    const w = window as unknown as Recorder;
    await w.chapgame.loadScene(sc);
    w.chapgame.ui.setState({ message: null });
    w.__messages = [];
    w.__unsubscribe?.();
    w.__unsubscribe = w.chapgame.ui.subscribe((s, p) => {
      if (s.message !== p.message && s.message !== null) w.__messages.push(s.message.text);
    });
  }, SCENE);
  await editor.page.getByRole("table", { name: "Bodies" }).getByLabel("b x", { exact: true }).waitFor();
}

const messages = () => editor.page.evaluate(() => (window as unknown as Recorder).__messages);
const shown = () => editor.page.locator(".message-slot .message > span").first().textContent();

/** Where world point (x, y) is on the page at the current view. */
async function onPage(x: number, y: number) {
  const box = (await editor.page.getByTestId("scene-canvas").boundingBox())!;
  const view = await editor.page.evaluate(() => (window as unknown as Recorder).chapgame.ui.getState().view);
  return {
    x: box.x + box.width / 2 + (x - view.cx) * view.scale,
    y: box.y + box.height / 2 - (y - view.cy) * view.scale,
  };
}

async function drag(tool: string, from: { x: number; y: number }, dx: number, dy: number): Promise<void> {
  await editor.page.getByRole("button", { name: tool, exact: true }).click();
  await editor.page.mouse.move(from.x, from.y);
  await editor.page.mouse.down();
  await editor.page.mouse.move(from.x + dx, from.y + dy, { steps: 12 });
  await editor.page.mouse.up();
}

/** Runs `edit`, then waits for its one message, which must match `expected`; the stage stays put. */
async function confirmed(edit: () => Promise<void>, expected: RegExp): Promise<string> {
  const stage = await stageBoxes(editor.page);
  const before = (await messages()).length;
  await edit();
  await poll(async () => (await messages()).length).toBeGreaterThan(before);
  // a drag's moves gave none: one message, at its end
  await new Promise((r) => setTimeout(r, 300));
  const said = (await messages()).slice(before);
  expect(said).toHaveLength(1);
  expect(said[0]).toMatch(expected);
  expect(await shown()).toBe(said[0]);
  expect(await stageBoxes(editor.page), "the message moved the stage").toBe(stage);
  return said[0]!;
}

const NUM = String.raw`-?[\d.]+(e[-+]?\d+)?`;
const VEC = String.raw`\(${NUM}, ${NUM}\)`;

describe("each edit says what it changed and how to undo it", () => {
  it("a Move drag, once at its release", async () => {
    await fresh();
    const a = await onPage(0, 0);
    await confirmed(
      () => drag("Move", a, 0, -60),
      new RegExp(`^Moved disc "a" to \\(0, ${NUM}\\) at t = 0 s \\(Undo moves it back to \\(0, 0\\)\\)\\.$`),
    );
  });

  it("a Velocity drag, once at its release", async () => {
    await fresh();
    const b = await onPage(10, 0);
    await confirmed(
      () => drag("Velocity", b, 40, 30),
      new RegExp(`^Set disc "b"'s velocity to ${VEC} at t = 0 s \\(Undo restores \\(0, 0\\)\\)\\.$`),
    );
  });

  it("a Cue strike", async () => {
    await fresh();
    await editor.page.getByRole("button", { name: "Cue", exact: true }).click();
    const rim = await onPage(-0.9, 0);
    await confirmed(
      () => editor.page.mouse.click(rim.x, rim.y),
      new RegExp(`^Struck disc "a": velocity \\(${NUM}, 0\\) at t = 0 s \\(Undo restores \\(0, 0\\)\\)\\.$`),
    );
  });

  it("a table cell, and Undo restores what it said", async () => {
    await fresh();
    const cell = editor.page.getByRole("table", { name: "Bodies" }).getByLabel("b r", { exact: true });
    await confirmed(async () => {
      await cell.click();
      await editor.page.keyboard.type("2");
      await editor.page.keyboard.press("Enter");
    }, /^Set disc "b" r = 2 at t = 0 s \(Undo restores r = 1\)\.$/);
    await editor.page.getByRole("button", { name: "Undo", exact: true }).click();
    await poll(() => cell.textContent()).toBe("1");
  });

  it("in a short window (700 × 420) the message keeps to its slot: the stage does not move", async () => {
    await withWindowSize(editor.page, 700, 420, async () => {
      await fresh();
      const cell = editor.page.getByRole("table", { name: "Bodies" }).getByLabel("a m", { exact: true });
      await confirmed(async () => {
        await cell.click();
        await editor.page.keyboard.type("Infinity");
        await editor.page.keyboard.press("Enter");
      }, /^Set disc "a" m = ∞ at t = 0 s \(Undo restores m = 1\)\.$/);
    });
  });
});
