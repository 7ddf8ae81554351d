/**
 * End-to-end: what a demanding scene author meets on the canvas and around it, in Debian's
 * Chromium: Fit with a lone disc, Escape cancelling a drag, what the pointer puts in the scene (at
 * its precision, not the digits of its position), a scene file dropped on the page, two tabs
 * autosaving side by side (and an autosave of the earlier single-slot version).
 */
import type { JSHandle, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { openEditor, type Session, screenshot } from "./harness.js";

const poll = <T>(fn: () => T | Promise<T>) => expect.poll(fn, { timeout: 15_000, interval: 50 });

let s: Session;
let page: Page;

const LONELY = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id: "lonely", x: 0, y: 0, r: 1, m: 1 }],
};

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
  await page.evaluate(async (sc) => {
    await (window as unknown as { chapgame: PageEditor }).chapgame.loadScene(sc);
  }, scene);
  await page.getByRole("table", { name: "Bodies" }).getByLabel(`${id} x`, { exact: true }).waitFor();
}

const actionCount = () =>
  page.evaluate(() => (window as unknown as { chapgame: PageEditor }).chapgame.doc.actions.length);

const editorState = () =>
  page.evaluate(() => {
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
  const box = (await page.getByTestId("scene-canvas").boundingBox())!;
  const { view } = await editorState();
  return {
    x: box.x + box.width / 2 + (x - view.cx) * view.scale,
    y: box.y + box.height / 2 - (y - view.cy) * view.scale,
    scale: view.scale,
    width: box.width,
  };
}

beforeAll(async () => {
  s = await openEditor();
  page = s.page;
});

afterAll(async () => {
  await s?.close();
});

describe("scene author", () => {
  it("Fit with a lone disc shows a disc in a space (a fifth of the canvas wide), not a disc filling it", async () => {
    await load(LONELY, "lonely");
    await page.getByRole("button", { name: "Fit", exact: true }).click();
    await poll(async () => {
      const p = await onPage(0, 0);
      return (2 * p.scale) / (p.width - 48);
    }).toBeCloseTo(0.2, 6);
    await screenshot(page, "14-fit-lone-disc");
  });

  it("Escape during a drag (disc, velocity handle, line end) restores the state and records nothing", async () => {
    await load(LONELY, "lonely");
    const before = await editorState();
    for (const tool of ["Move", "Velocity", "Segment"]) {
      await page.getByRole("button", { name: tool, exact: true }).click();
      const c = await onPage(0, 0);
      await page.mouse.move(c.x, c.y);
      await page.mouse.down();
      await page.mouse.move(c.x + 60, c.y - 40, { steps: 6 });
      await page.keyboard.press("Escape");
      await page.mouse.move(c.x + 90, c.y - 60, { steps: 3 });
      await page.mouse.up();
      await page.waitForTimeout(300); // an edit would be in the worker's hands by now
      const after = await editorState();
      expect(after.actions, tool).toBe(before.actions);
      expect(after.past, tool).toBe(before.past);
      expect(after.view, tool).toEqual(before.view);
    }
    const bodies = page.getByRole("table", { name: "Bodies" });
    expect(await bodies.getByLabel("lonely x", { exact: true }).textContent()).toBe("0");
    expect(await bodies.getByLabel("lonely vx", { exact: true }).textContent()).toBe("0");
    expect(await page.getByRole("table", { name: "Lines" }).getByRole("row").count()).toBe(1);
    // the control: the same move drag without Escape moves the disc
    await page.getByRole("button", { name: "Move", exact: true }).click();
    const c = await onPage(0, 0);
    await page.mouse.move(c.x, c.y);
    await page.mouse.down();
    await page.mouse.move(c.x + 60, c.y, { steps: 6 });
    await page.mouse.up();
    await poll(async () =>
      Number(await bodies.getByLabel("lonely x", { exact: true }).textContent()),
    ).toBeCloseTo(60 / c.scale, 1);
  });

  it("the pointer puts places at its precision: a clicked disc, a dragged one and a drawn segment, at 37 px per unit to 0.01", async () => {
    await load(LONELY, "lonely");
    // a pixel is 0.027 units: the coarsest power of ten under it is 0.01
    await page.evaluate(() => {
      (window as unknown as { chapgame: PageEditor }).chapgame.ui.setState({
        view: { cx: 0, cy: 0, scale: 37 },
      });
    });
    const c = await onPage(0, 0);
    await page.getByRole("button", { name: "Disc", exact: true }).click();
    await page.mouse.click(c.x + 123.4567, c.y - 45.678); // (3.3367…, 1.2345…)
    const bodies = page.getByRole("table", { name: "Bodies" });
    await bodies.getByLabel("b1 x", { exact: true }).waitFor();
    await page.getByRole("button", { name: "Move", exact: true }).click();
    await page.mouse.move(c.x, c.y);
    await page.mouse.down();
    await page.mouse.move(c.x - 200.3, c.y + 10.7, { steps: 5 }); // (−5.4135…, −0.2891…)
    await page.mouse.up();
    await page.getByRole("button", { name: "Segment", exact: true }).click();
    await page.mouse.move(c.x - 100.25, c.y + 150.55); // (−2.7094…, −4.0689…)
    await page.mouse.down();
    await page.mouse.move(c.x + 180.77, c.y + 150.55, { steps: 5 }); // (4.8856…, −4.0689…)
    await page.mouse.up();
    await page.getByRole("table", { name: "Lines" }).getByLabel("l1 x1", { exact: true }).waitFor();
    await poll(() => actionCount()).toBe(4);
    const actions = (await page.evaluate(
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
    const bodies = page.getByRole("table", { name: "Bodies" });
    const rows = () => bodies.getByRole("row").count();
    const message = () => page.locator(".message").textContent();
    const PAIR = {
      ...LONELY,
      actions: [
        { time: 0, type: "addBody", id: "left", x: -3, y: 0, r: 1, m: 1 },
        { time: 0, type: "addBody", id: "right", x: 3, y: 0, r: 1, m: 1 },
      ],
    };
    /** A drag of files (name, text, type) as the browser hands it to the page. */
    const files = (list: [string, string, string][]): Promise<JSHandle<DataTransfer>> =>
      page.evaluateHandle((l) => {
        const dt = new DataTransfer();
        for (const [name, text, type] of l) dt.items.add(new File([text], name, { type }));
        return dt;
      }, list);
    const drop = async (dataTransfer: JSHandle<DataTransfer>) => {
      const canvas = page.getByTestId("scene-canvas");
      await canvas.dispatchEvent("dragenter", { dataTransfer });
      await canvas.dispatchEvent("dragover", { dataTransfer });
      await page.getByRole("status", { name: "Drop indicator" }).waitFor();
      await screenshot(page, "15-drop-indicator");
      await canvas.dispatchEvent("drop", { dataTransfer });
      await page.getByRole("status", { name: "Drop indicator" }).waitFor({ state: "detached" });
    };

    await drop(await files([["pair.chapgame.json", JSON.stringify(PAIR), "application/json"]]));
    await bodies.getByLabel("right x", { exact: true }).waitFor();
    expect(await rows()).toBe(3);
    await poll(message).toMatch(/^Opened pair\.chapgame\.json\. Undo returns/);
    await page.getByRole("button", { name: "Undo" }).click();
    await bodies.getByLabel("lonely x", { exact: true }).waitFor();

    // refusals: the message says why, the scene stays
    const bad = JSON.stringify({ ...LONELY, actions: [{ ...LONELY.actions[0], m: -1 }] });
    await drop(await files([["bad.json", bad, "application/json"]]));
    await poll(message).toMatch(/^bad\.json: actions\[0\]\.m: /);
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

    await loadIn(page, one("tabA"));
    await shows(page, "tabA");
    await page.waitForTimeout(600); // autosaved (300 ms of quiet)
    const b = await s.context.newPage();
    try {
      await b.goto(s.url);
      await shows(b, "tabA"); // a fresh tab opens the most recently saved scene
      await loadIn(b, one("tabB"));
      await shows(b, "tabB");
      // tab A is told, without a modal, and keeps its own scene
      await notice(page).waitFor({ timeout: 5000 });
      expect(await notice(page).textContent()).toMatch(/^Another editor tab saved a newer scene at /);
      await screenshot(page, "16-newer-work-in-another-tab");
      await page.reload();
      await shows(page, "tabA");
      await notice(page).waitFor(); // still offered after the reload
      await b.reload();
      await shows(b, "tabB");
      // A opens B's work; Undo brings A's back
      await notice(page).getByRole("button", { name: "Open it" }).click();
      await shows(page, "tabB");
      await page.getByRole("button", { name: "Undo" }).click();
      await shows(page, "tabA");
    } finally {
      await b.close();
    }
  });

  it("the single autosave of the earlier version is restored by a fresh tab", async () => {
    const legacy = { ...LONELY, actions: [{ ...LONELY.actions[0], id: "fromV1" }] };
    // no other editor tab open (an open tab writes its slot back when it is removed)
    await page.goto("about:blank");
    const c = await s.context.newPage();
    try {
      // the storage as the earlier version left it, set before the editor starts
      await c.addInitScript((text) => {
        if (sessionStorage.getItem("e2e.setup")) return;
        sessionStorage.setItem("e2e.setup", "1");
        for (const key of Object.keys(localStorage))
          if (key.startsWith("chapgame.editor.autosave.")) localStorage.removeItem(key);
        localStorage.setItem("chapgame.editor.autosave.v1", text);
      }, JSON.stringify(legacy));
      await c.goto(s.url);
      await c.getByRole("table", { name: "Bodies" }).getByLabel("fromV1 x", { exact: true }).waitFor();
      expect(await c.evaluate(() => localStorage.getItem("chapgame.editor.autosave.v1"))).toBeNull();
    } finally {
      await c.close();
      await page.goto(s.url);
    }
  });
});
