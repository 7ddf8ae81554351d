/**
 * End-to-end, in Debian's Chromium: the Event log fits its box at every window size, with no
 * sideways scroll. In a short window (700 × 420) its box is 249 px wide and the log was 336: the
 * participants column hid under the sticky ✕ column and was reached only by a sideways scroll. The
 * kind and participants columns now share what the time and the ✕ leave (tables.css), their text cut
 * with an ellipsis where it is longer and whole in the cell's title; each ✕ stays in the box, at
 * least 24 × 24 px, uncovered. In a wide window nothing is cut.
 */
import { describe, expect, it } from "vitest";
import { editorForFile } from "./editorForFile.js";
import { sceneFile } from "./editorScenes.js";
import { loadScene } from "./pageEditor.js";
import { forEachWindowSize } from "./windowSize.js";

const editor = editorForFile({ width: 700, height: 420 });

/** A striker struck at t = 0.5 into two balls and a cushion: collisions of long-ish ids, and action entries with a ✕. */
const SCENE = sceneFile([
  { time: 0, type: "addLine", id: "cushion_right", p1: [30, -50], p2: [30, 50], kind: "line" },
  { time: 0, type: "addBody", id: "striker", x: 0, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] },
  { time: 0, type: "addBody", id: "ball10", x: 10, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] },
  { time: 0, type: "addBody", id: "ball11", x: 20, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] },
  { time: 0.5, type: "giveVelocity", id: "striker", v: [10, 0] },
]);

/** The log's box and table widths, its ✕ buttons' boxes (in the box or not, uncovered or not), and
 *  its cut cells (text wider than the cell) with their titles. */
function logLayout() {
  return editor.page.evaluate(() => {
    const table = document.querySelector<HTMLElement>('table[aria-label="Event log"]')!;
    const box = table.closest<HTMLElement>(".table-scroll")!;
    box.scrollIntoView({ block: "nearest" });
    const b = box.getBoundingClientRect();
    const buttons = Array.from(table.querySelectorAll<HTMLButtonElement>("tbody button")).map((el) => {
      el.scrollIntoView({ block: "nearest" });
      const r = el.getBoundingClientRect();
      const at = document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2);
      return {
        width: r.width,
        height: r.height,
        inBox: r.left >= b.left - 0.5 && r.right <= b.left + box.clientWidth + 0.5,
        uncovered: el.contains(at),
      };
    });
    const cells = Array.from(table.querySelectorAll<HTMLElement>("tbody td"));
    const cut = cells
      .filter((td) => td.scrollWidth > td.clientWidth + 0.5)
      .map((td) => ({ text: td.textContent, title: td.title }));
    return {
      scrollWidth: box.scrollWidth,
      clientWidth: box.clientWidth,
      buttons,
      cut,
      rows: table.querySelectorAll("tbody tr:not(.spacer)").length,
    };
  });
}

describe("the Event log", () => {
  it("fits its box in short and narrow windows, each ✕ in it, 24 px, uncovered; a cut text is whole in its title", async () => {
    await loadScene(
      editor.page,
      SCENE,
      { useTime: true, seconds: 5, useEvents: false, autoExtend: false },
      60_000,
    );
    await forEachWindowSize(
      editor.page,
      [
        [700, 420],
        [667, 375],
        [844, 390],
        [700, 900],
      ],
      async (width, height) => {
        await editor.page.waitForTimeout(300); // a resize's layout and the log's refresh
        const s = await logLayout();
        const at = `${width} x ${height}`;
        expect(s.rows, at).toBeGreaterThanOrEqual(8);
        expect(s.scrollWidth, `${at}: no sideways scroll`).toBeLessThanOrEqual(s.clientWidth);
        expect(s.buttons.length, at).toBeGreaterThanOrEqual(5);
        for (const btn of s.buttons) {
          expect(btn.width, at).toBeGreaterThanOrEqual(24);
          expect(btn.height, at).toBeGreaterThanOrEqual(24);
          expect(btn.inBox, at).toBe(true);
          expect(btn.uncovered, at).toBe(true);
        }
        if (width === 700 && height === 420)
          expect(s.cut.length, "the narrow box cuts some text").toBeGreaterThan(0);
        for (const c of s.cut) expect(c.title, `${at}: a cut cell's title holds its text`).toBe(c.text);
      },
    );
  });

  it("cuts nothing in a wide window", async () => {
    await forEachWindowSize(editor.page, [[1400, 900]], async () => {
      await editor.page.waitForTimeout(300);
      const s = await logLayout();
      expect(s.scrollWidth).toBeLessThanOrEqual(s.clientWidth);
      expect(s.cut).toEqual([]);
    });
  });
});
