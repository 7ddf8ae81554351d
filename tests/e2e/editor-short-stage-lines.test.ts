/**
 * End-to-end, in Debian's Chromium: a short window from 901 to 1099 px wide (at most 500 px high)
 * takes both the short window's layout (short.css) and the narrow toolbar's tighter spacing
 * (toolbar.css). There the toolbar is one line, as high as in a wide short window (1280 x 480), its
 * controls uncovered; the time bar is as high as there; each persistent notice, both shown, keeps
 * to one line; and the canvas keeps at least half its height (and 90 px) uncovered by them, the
 * page fitting the window. At 950 x 450 short.css's wider button padding won over the narrow
 * toolbar's, and ? wrapped onto a second line (the toolbar 52 px high, not 29: 23 px of canvas).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { newerNotice, noticesBottom, refusedNotice, setNotices } from "./notices.js";
import { buttonUncovered } from "./stageProbes.js";
import { forEachWindowSize, type WindowSize, withWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** Short windows where the narrow toolbar's rules apply too (901 to 1099 px wide). */
const SIZES: WindowSize[] = [
  [901, 500],
  [950, 450],
  [1000, 480],
  [1050, 480],
  [1099, 500],
];

/** A wide short window: one toolbar line, as short.css alone lays it out. */
const WIDE_SHORT: WindowSize = [1280, 480];

/** The toolbar's and the time bar's heights, the tops of the toolbar's controls, the canvas's
 *  height, each notice's height, and the page's scroll height against the window's. */
function shortStage() {
  return editor.page.evaluate(() => {
    const box = (sel: string) => document.querySelector(sel)!.getBoundingClientRect();
    const tops = Array.from(document.querySelectorAll(".toolbar > button, .toolbar > label")).map(
      (el) => el.getBoundingClientRect().top,
    );
    const notices = Array.from(document.querySelectorAll(".stage-notices > *")).map(
      (n) => n.getBoundingClientRect().height,
    );
    const page = document.scrollingElement!;
    return {
      toolbar: box(".toolbar").height,
      timebar: box(".timebar").height,
      canvas: box("[data-testid=scene-canvas]").height,
      tops,
      notices,
      fits: page.scrollHeight <= page.clientHeight,
    };
  });
}

describe("a short window from 901 to 1099 px wide", () => {
  it("keeps the toolbar on one line, each notice on one line and half the canvas uncovered", async () => {
    const wide = await withWindowSize(editor.page, ...WIDE_SHORT, shortStage);
    try {
      await forEachWindowSize(editor.page, SIZES, async (width, height) => {
        const at = `${width} x ${height}`;
        const bare = await shortStage();
        expect(bare.tops.length, at).toBe(13);
        expect(Math.max(...bare.tops) - Math.min(...bare.tops), `${at}: toolbar tops`).toBeLessThan(4);
        expect(bare.toolbar, `${at}: toolbar`).toBe(wide.toolbar);
        expect(bare.timebar, `${at}: time bar`).toBe(wide.timebar);
        for (const name of ["Move", "Fit", "Delete", "Keyboard shortcuts", "Next event", "Play"])
          expect(await buttonUncovered(editor.page, name), `${at}: ${name}`).toBe(true);

        await setNotices(editor.page, true, true);
        await poll(
          async () => (await newerNotice(editor.page).count()) + (await refusedNotice(editor.page).count()),
        ).toBe(2);
        const shown = await shortStage();
        expect(shown.fits, `${at}: the page fits the window`).toBe(true);
        expect(shown.canvas, `${at}: the canvas as high as without them`).toBe(bare.canvas);
        for (const h of shown.notices) expect(h, `${at}: a notice on one line`).toBeLessThan(30);
        const uncovered = shown.canvas - (await noticesBottom(editor.page));
        expect(uncovered, `${at}: canvas uncovered`).toBeGreaterThanOrEqual(Math.max(90, shown.canvas / 2));
        await screenshot(editor.page, `short-stage-lines-${width}x${height}`);
        await setNotices(editor.page, false, false);
      });
    } finally {
      await setNotices(editor.page, false, false);
    }
  });
});
