/**
 * End-to-end: what a demanding scene author meets on the canvas and around it, in Debian's
 * Chromium: Fit with a lone disc, Escape cancelling a drag, what the pointer puts in the scene (at
 * its precision, not the digits of its position), a scene file dropped on the page, two tabs
 * autosaving side by side (and an autosave of the earlier single-slot version).
 */
import type { JSHandle, Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { LONELY } from "./editorScenes.js";
import { screenshot } from "./harness.js";

const editor = editorForFile();

type PageEditor = {
  doc: { actions: unknown[] };
  ui: {
    getState(): { view: { cx: number; cy: number; scale: number }; playing: boolean };
    setState(patch: object): void;
  };
  history: { getState(): { past: unknown[] } };
  loadScene(scene: unknown, options?: object): Promise<string | null>;
};

/** Loads a scene through the page's editor (fitted, like a preset) and waits for its first body row. */
async function load(scene: unknown, id: string) {
  await editor.page.evaluate(async (sc) => {
    await (window as unknown as { chapgame: PageEditor }).chapgame.loadScene(sc);
  }, scene);
  await editor.page.getByRole("table", { name: "Bodies" }).getByLabel(`${id} x`, { exact: true }).waitFor();
}

const actionCount = () =>
  editor.page.evaluate(() => (window as unknown as { chapgame: PageEditor }).chapgame.doc.actions.length);

const editorState = () =>
  editor.page.evaluate(() => {
    const ed = (window as unknown as { chapgame: PageEditor }).chapgame;
    return {
      actions: ed.doc.actions.length,
      past: ed.history.getState().past.length,
      view: ed.ui.getState().view,
      playing: ed.ui.getState().playing,
    };
  });

/** Where world point (x, y) is on the page at the current view. */
async function onPage(x: number, y: number) {
  const box = (await editor.page.getByTestId("scene-canvas").boundingBox())!;
  const { view } = await editorState();
  return {
    x: box.x + box.width / 2 + (x - view.cx) * view.scale,
    y: box.y + box.height / 2 - (y - view.cy) * view.scale,
    scale: view.scale,
    width: box.width,
  };
}

describe("scene author", () => {
  it("Fit with a lone disc shows a disc in a space (a fifth of the canvas wide), not a disc filling it", async () => {
    await load(LONELY, "lonely");
    await editor.page.getByRole("button", { name: "Fit", exact: true }).click();
    await poll(async () => {
      const p = await onPage(0, 0);
      return (2 * p.scale) / (p.width - 48);
    }).toBeCloseTo(0.2, 6);
    await screenshot(editor.page, "14-fit-lone-disc");
  });

  it("Escape during a drag (disc, velocity handle, line end) restores the state and records nothing", async () => {
    await load(LONELY, "lonely");
    const before = await editorState();
    for (const tool of ["Move", "Velocity", "Segment"]) {
      await editor.page.getByRole("button", { name: tool, exact: true }).click();
      const c = await onPage(0, 0);
      await editor.page.mouse.move(c.x, c.y);
      await editor.page.mouse.down();
      await editor.page.mouse.move(c.x + 60, c.y - 40, { steps: 6 });
      await editor.page.keyboard.press("Escape");
      await editor.page.mouse.move(c.x + 90, c.y - 60, { steps: 3 });
      await editor.page.mouse.up();
      await editor.page.waitForTimeout(300); // an edit would be in the worker's hands by now
      const after = await editorState();
      expect(after.actions, tool).toBe(before.actions);
      expect(after.past, tool).toBe(before.past);
      expect(after.view, tool).toEqual(before.view);
    }
    const bodies = editor.page.getByRole("table", { name: "Bodies" });
    expect(await bodies.getByLabel("lonely x", { exact: true }).textContent()).toBe("0");
    expect(await bodies.getByLabel("lonely vx", { exact: true }).textContent()).toBe("0");
    expect(await editor.page.getByRole("table", { name: "Lines" }).getByRole("row").count()).toBe(1);
    // the control: the same move drag without Escape moves the disc
    await editor.page.getByRole("button", { name: "Move", exact: true }).click();
    const c = await onPage(0, 0);
    await editor.page.mouse.move(c.x, c.y);
    await editor.page.mouse.down();
    await editor.page.mouse.move(c.x + 60, c.y, { steps: 6 });
    await editor.page.mouse.up();
    await poll(async () =>
      Number(await bodies.getByLabel("lonely x", { exact: true }).textContent()),
    ).toBeCloseTo(60 / c.scale, 1);
  });

  it("the pointer puts places at its precision: a clicked disc, a dragged one and a drawn segment, at 37 px per unit to 0.01", async () => {
    await load(LONELY, "lonely");
    // a pixel is 0.027 units: the coarsest power of ten under it is 0.01
    await editor.page.evaluate(() => {
      (window as unknown as { chapgame: PageEditor }).chapgame.ui.setState({
        view: { cx: 0, cy: 0, scale: 37 },
      });
    });
    const c = await onPage(0, 0);
    await editor.page.getByRole("button", { name: "Disc", exact: true }).click();
    await editor.page.mouse.click(c.x + 123.4567, c.y - 45.678); // (3.3367…, 1.2345…)
    const bodies = editor.page.getByRole("table", { name: "Bodies" });
    await bodies.getByLabel("b1 x", { exact: true }).waitFor();
    await editor.page.getByRole("button", { name: "Move", exact: true }).click();
    await editor.page.mouse.move(c.x, c.y);
    await editor.page.mouse.down();
    await editor.page.mouse.move(c.x - 200.3, c.y + 10.7, { steps: 5 }); // (−5.4135…, −0.2891…)
    await editor.page.mouse.up();
    await editor.page.getByRole("button", { name: "Segment", exact: true }).click();
    await editor.page.mouse.move(c.x - 100.25, c.y + 150.55); // (−2.7094…, −4.0689…)
    await editor.page.mouse.down();
    await editor.page.mouse.move(c.x + 180.77, c.y + 150.55, { steps: 5 }); // (4.8856…, −4.0689…)
    await editor.page.mouse.up();
    await editor.page.getByRole("table", { name: "Lines" }).getByLabel("l1 x1", { exact: true }).waitFor();
    await poll(() => actionCount()).toBe(4);
    const actions = (await editor.page.evaluate(
      () => (window as unknown as { chapgame: PageEditor }).chapgame.doc.actions,
    )) as Record<string, unknown>[];
    expect(actions.slice(1).map((a) => a.type)).toEqual(["addBody", "updateBody", "addLine"]);
    const [disc, moved, line] = actions.slice(1) as [
      { x: number; y: number },
      { x: number; y: number },
      { p1: [number, number]; p2: [number, number] },
    ];
    // each within a pixel (0.027) of where the pointer was, with at most two decimals
    const aimed: [number, number][] = [
      [disc.x, 3.3367],
      [disc.y, 1.2345],
      [moved.x, -5.4135],
      [moved.y, -0.2891],
      [line.p1[0], -2.7094],
      [line.p2[0], 4.8856],
      [line.p1[1], -4.0689],
    ];
    for (const [got, aim] of aimed) {
      expect(Math.abs(got - aim)).toBeLessThan(0.03);
      expect(String(got)).toMatch(/^-?\d+(\.\d{1,2})?$/);
    }
    expect(line.p2[1]).toBe(line.p1[1]); // drawn level, it stays level
    // the tables show the same short numbers
    expect(await bodies.getByLabel("b1 x", { exact: true }).textContent()).toBe(String(disc.x));
    await poll(() => bodies.getByLabel("lonely x", { exact: true }).textContent()).toBe(String(moved.x));
  });

  it("a scene file dropped on the page opens like Load file: indicator while dragging, Undo, refusals", async () => {
    await load(LONELY, "lonely");
    const bodies = editor.page.getByRole("table", { name: "Bodies" });
    const rows = () => bodies.getByRole("row").count();
    const message = () => editor.page.locator(".message").textContent();
    const PAIR = {
      ...LONELY,
      actions: [
        { time: 0, type: "addBody", id: "left", x: -3, y: 0, r: 1, m: 1 },
        { time: 0, type: "addBody", id: "right", x: 3, y: 0, r: 1, m: 1 },
      ],
    };
    /** A drag of files (name, text, type) as the browser hands it to the page. */
    const files = (list: [string, string, string][]): Promise<JSHandle<DataTransfer>> =>
      editor.page.evaluateHandle((l) => {
        const dt = new DataTransfer();
        for (const [name, text, type] of l) dt.items.add(new File([text], name, { type }));
        return dt;
      }, list);
    const drop = async (dataTransfer: JSHandle<DataTransfer>) => {
      const canvas = editor.page.getByTestId("scene-canvas");
      await canvas.dispatchEvent("dragenter", { dataTransfer });
      await canvas.dispatchEvent("dragover", { dataTransfer });
      await editor.page.getByRole("status", { name: "Drop indicator" }).waitFor();
      await screenshot(editor.page, "15-drop-indicator");
      await canvas.dispatchEvent("drop", { dataTransfer });
      await editor.page.getByRole("status", { name: "Drop indicator" }).waitFor({ state: "detached" });
    };

    await drop(await files([["pair.chapgame.json", JSON.stringify(PAIR), "application/json"]]));
    await bodies.getByLabel("right x", { exact: true }).waitFor();
    expect(await rows()).toBe(3);
    await poll(message).toMatch(/^Opened pair\.chapgame\.json\. Undo returns/);
    await editor.page.getByRole("button", { name: "Undo" }).click();
    await bodies.getByLabel("lonely x", { exact: true }).waitFor();

    // refusals: the message says why, the scene stays
    const bad = JSON.stringify({ ...LONELY, actions: [{ ...LONELY.actions[0], m: -1 }] });
    await drop(await files([["bad.json", bad, "application/json"]]));
    // the action named as the author knows it, the engine's path in parentheses
    await poll(message).toMatch(
      /^bad\.json: the action at t = 0 s that adds disc "lonely" \(actions\[0\]\.m\): /,
    );
    await drop(await files([["photo.png", "PNG", "image/png"]]));
    await poll(message).toMatch(/^photo\.png: not a scene file/);
    await drop(
      await files([
        ["a.json", JSON.stringify(PAIR), "application/json"],
        ["b.json", JSON.stringify(PAIR), "application/json"],
      ]),
    );
    await poll(message).toMatch(/^Drop one scene file at a time \(2 files/);
    expect(await rows()).toBe(2);
    expect(await bodies.getByLabel("lonely x", { exact: true }).count()).toBe(1);
  });

  it("two tabs autosave side by side: a reload keeps each tab's own scene, the other's newer work is offered", async () => {
    const one = (id: string) => ({ ...LONELY, actions: [{ ...LONELY.actions[0], id }] });
    const shows = (p: Page, id: string) =>
      p.getByRole("table", { name: "Bodies" }).getByLabel(`${id} x`, { exact: true }).waitFor();
    const loadIn = (p: Page, scene: unknown) =>
      p.evaluate(async (sc) => {
        await (window as unknown as { chapgame: PageEditor }).chapgame.loadScene(sc);
      }, scene);
    const notice = (p: Page) => p.getByRole("status", { name: "Newer work in another tab" });

    await loadIn(editor.page, one("tabA"));
    await shows(editor.page, "tabA");
    await editor.page.waitForTimeout(600); // autosaved (300 ms of quiet)
    const b = await editor.session.context.newPage();
    try {
      await b.goto(editor.session.url);
      await shows(b, "tabA"); // a fresh tab opens the most recently saved scene
      await loadIn(b, one("tabB"));
      await shows(b, "tabB");
      // tab A is told, without a modal, and keeps its own scene
      await notice(editor.page).waitFor({ timeout: 5000 });
      expect(await notice(editor.page).textContent()).toMatch(/^Another editor tab saved a newer scene at /);
      await screenshot(editor.page, "16-newer-work-in-another-tab");
      await editor.page.reload();
      await shows(editor.page, "tabA");
      await notice(editor.page).waitFor(); // still offered after the reload
      await b.reload();
      await shows(b, "tabB");
      // A opens B's work; Undo brings A's back
      await notice(editor.page).getByRole("button", { name: "Open it" }).click();
      await shows(editor.page, "tabB");
      await editor.page.getByRole("button", { name: "Undo" }).click();
      await shows(editor.page, "tabA");
    } finally {
      await b.close();
    }
  });

  it("the single autosave of the earlier version is restored by a fresh tab", async () => {
    const legacy = { ...LONELY, actions: [{ ...LONELY.actions[0], id: "fromV1" }] };
    // no other editor tab open (an open tab writes its slot back when it is removed)
    await editor.page.goto("about:blank");
    const c = await editor.session.context.newPage();
    try {
      // the storage as the earlier version left it, set before the editor starts
      await c.addInitScript((text) => {
        if (sessionStorage.getItem("e2e.setup")) return;
        sessionStorage.setItem("e2e.setup", "1");
        for (const key of Object.keys(localStorage))
          if (key.startsWith("chapgame.editor.autosave.")) localStorage.removeItem(key);
        localStorage.setItem("chapgame.editor.autosave.v1", text);
      }, JSON.stringify(legacy));
      await c.goto(editor.session.url);
      await c.getByRole("table", { name: "Bodies" }).getByLabel("fromV1 x", { exact: true }).waitFor();
      expect(await c.evaluate(() => localStorage.getItem("chapgame.editor.autosave.v1"))).toBeNull();
    } finally {
      await c.close();
      await editor.page.goto(editor.session.url);
    }
  });
});
