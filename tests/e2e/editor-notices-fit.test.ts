/**
 * End-to-end, in Debian's Chromium: Fit leaves out the strip of the canvas the persistent notices
 * hang over. A scene taller than the canvas (a column of discs: its top disc is at the fitted view's
 * top, 24 px below the canvas's) fitted
 * while a notice or both are shown has every disc below them, by Fit, by loading a scene (its fit)
 * and by a notice coming over a fitted view; dismissed, the view is fitted to the whole canvas again.
 * Fit once ignored them: the top rows of discs were under the notices.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { noticesBottom, setNotices } from "./notices.js";

const editor = editorForFile({ width: 1280, height: 800 });

/** The top of the highest disc drawn, in CSS px below the canvas's top (the view and the latest
 *  frame, as the canvas draws them; NaN before a frame). */
function discsTop(): Promise<number> {
  return editor.page.evaluate(() => {
    type Editor = {
      ui: { getState(): { view: { cy: number; scale: number } } };
      client: { latestFrame: { ids: string[]; data: Float64Array } | null };
    };
    const ed = (window as unknown as { chapgame: Editor }).chapgame;
    const f = ed.client.latestFrame;
    if (!f || f.ids.length === 0) return Number.NaN;
    const { cy, scale } = ed.ui.getState().view;
    const height = document.querySelector("[data-testid=scene-canvas]")!.getBoundingClientRect().height;
    let top = Number.POSITIVE_INFINITY;
    for (let i = 0; i < f.ids.length; i++) {
      const y = f.data[i * 11 + 1]!;
      const r = f.data[i * 11 + 6]!;
      top = Math.min(top, height / 2 - (y - cy) * scale - r * scale);
    }
    return top;
  });
}

const fit = () => editor.page.getByRole("button", { name: "Fit", exact: true }).click();

/** A column of nine discs at rest, 600 units high: the height sets a fitted view's scale. */
const COLUMN = {
  format: "chapgame",
  version: 1,
  g: 0,
  gravity: [0, 0],
  actions: Array.from({ length: 9 }, (_, i) => ({
    time: 0,
    type: "addBody",
    id: `c${i}`,
    x: 0,
    y: 300 - 75 * i,
    r: 10,
    m: 1,
  })),
};

/** Loads the column through the page's editor (fitted, like a preset or a file). */
async function loadColumn(): Promise<void> {
  await editor.page.evaluate(async (sc) => {
    type PageEditor = { loadScene(scene: unknown): Promise<string | null> };
    await (window as unknown as { chapgame: PageEditor }).chapgame.loadScene(sc);
  }, COLUMN);
  await editor.page.getByRole("table", { name: "Bodies" }).getByLabel("c8 x", { exact: true }).waitFor();
}

describe("Fit and the persistent notices", () => {
  it("a fitted scene's discs are never under the notices: Fit, a scene loaded, a notice coming and going", async () => {
    try {
      await setNotices(editor.page, false, false);
      await loadColumn();
      await fit();
      // fitted to the whole canvas, the top disc is 24 px from its top: where the notices hang
      await poll(discsTop).toBeCloseTo(24, 0);
      for (const [newer, refused, name] of [
        [true, false, "newer"],
        [false, true, "refused"],
        [true, true, "both"],
      ] as const) {
        await setNotices(editor.page, newer, refused);
        await poll(() => noticesBottom(editor.page)).toBeGreaterThan(20);
        const covered = await noticesBottom(editor.page);
        // a notice coming over the fitted view fits it again, below the notice
        await expect
          .poll(discsTop, { timeout: 15_000, interval: 50, message: `${name}: fitted again` })
          .toBeGreaterThanOrEqual(covered);
        await fit();
        await poll(discsTop).toBeGreaterThanOrEqual(covered);
        // the fit's margin below them: the rest of the canvas is used
        expect(await discsTop(), name).toBeCloseTo(covered + 24, 0);
        await screenshot(editor.page, `notices-fit-${name}`);
      }
      // a scene loaded while the notices are shown is fitted below them
      await loadColumn();
      const covered = await noticesBottom(editor.page);
      await poll(discsTop).toBeGreaterThanOrEqual(covered);
      // dismissed: the fitted view takes the whole canvas again
      await setNotices(editor.page, false, false);
      await poll(discsTop).toBeCloseTo(24, 0);
    } finally {
      await setNotices(editor.page, false, false);
    }
  });

  it("a view moved by the reader stays where it is when a notice comes", async () => {
    try {
      await fit();
      await poll(discsTop).toBeCloseTo(24, 0);
      const canvas = (await editor.page.getByTestId("scene-canvas").boundingBox())!;
      await editor.page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
      await editor.page.mouse.wheel(0, -200);
      // zoomed in around the centre: the top discs go above the canvas
      await poll(discsTop).toBeLessThan(0);
      const zoomed = await discsTop();
      await setNotices(editor.page, true, true);
      await poll(() => noticesBottom(editor.page)).toBeGreaterThan(20);
      await editor.page.waitForTimeout(300);
      expect(await discsTop()).toBe(zoomed);
    } finally {
      await setNotices(editor.page, false, false);
    }
  });
});
