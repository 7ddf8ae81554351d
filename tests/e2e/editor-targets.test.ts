/**
 * End-to-end, in Debian's Chromium: every button of the stage's toolbar and time bar (Time and
 * Speed), and the toolbar's checkbox labels (Trails, Path), are targets of at least 24 x 24 px
 * (WCAG 2.2, 2.5.8) at every window size the editor's end-to-end tests use, and no two of them
 * overlap. They were 21 px high at every width (13 px text, 2 px padding), ? 21 px wide and the
 * time bar's 0 button 22 in a short window, the labels 19 px high. That they did not cost the canvas
 * a line is editor-stage-lines' and editor-short-stage-lines' (the toolbar and the time bar as high
 * as before).
 */
import { describe, expect, it } from "vitest";
import { editorForFile } from "./editorForFile.js";
import { forEachWindowSize, type WindowSize } from "./windowSize.js";

const editor = editorForFile();

/** The WCAG 2.2 minimum target size (2.5.8), CSS px each way. */
const MIN_TARGET_PX = 24;

/** Every window size the editor's end-to-end tests use (two columns, short, stacked, phone). */
const SIZES: WindowSize[] = [
  [901, 900],
  [950, 900],
  [1000, 900],
  [1001, 900],
  [1050, 900],
  [1100, 900],
  [1200, 900],
  [1279, 900],
  [1280, 900],
  [1400, 900],
  [1920, 900],
  [1920, 1080],
  [2560, 1440],
  [1600, 900],
  [1280, 800],
  [1024, 700],
  [1000, 700],
  [900, 700],
  [800, 600],
  [700, 800],
  [400, 800],
  [390, 844],
  [950, 450],
  [1050, 480],
  [900, 500],
  [1280, 480],
  [844, 390],
  [740, 360],
  [700, 420],
  [667, 375],
];

/** Each stage target's name and box (its border box, what a pointer hits). */
function stageTargets() {
  return editor.page.evaluate(() =>
    Array.from(document.querySelectorAll(".toolbar button, .toolbar label, .timebar button")).map((el) => {
      const r = el.getBoundingClientRect();
      const name = el.getAttribute("aria-label") ?? el.textContent!.trim();
      return { name, x: r.x, y: r.y, width: r.width, height: r.height };
    }),
  );
}

describe("the stage's targets", () => {
  it("are at least 24 x 24 px at every window size, none overlapping another", async () => {
    await forEachWindowSize(editor.page, SIZES, async (width, height) => {
      const at = `${width} x ${height}`;
      const targets = await stageTargets();
      // the 8 tools, Fit, Trails, Path, Delete, ?; the zoom's 3, the steps' 5, Speed's 5
      expect(targets.length, at).toBe(26);
      for (const t of targets) {
        expect(t.width, `${at}: ${t.name} wide`).toBeGreaterThanOrEqual(MIN_TARGET_PX);
        expect(t.height, `${at}: ${t.name} high`).toBeGreaterThanOrEqual(MIN_TARGET_PX);
      }
      for (const [i, a] of targets.entries())
        for (const b of targets.slice(i + 1)) {
          const overlapX = Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x);
          const overlapY = Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y);
          expect(overlapX > 0.5 && overlapY > 0.5, `${at}: ${a.name} overlaps ${b.name}`).toBe(false);
        }
    });
  });
});
