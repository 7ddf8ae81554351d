/**
 * End-to-end, in Debian's Chromium: messages never move the canvas (a long one hangs over the side
 * column at 1280 px, cut to one line until More, and can be dismissed; at 800 x 600 it keeps to its
 * line in the header and the toolbar stays usable:
 * editor-narrow-messages.test.ts measures the stage for every kind of message at 700 and 900 px),
 * and small windows (1024 x 700 down to 390 x 844) keep the canvas, the Time slider and every time
 * and speed control usable, nothing overflowing sideways; from 700 to 900 px the Time slider widens
 * with the window (Speed goes under Time rather than squeeze it).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { longRefusal, showMessage } from "./messages.js";
import { loadPresetOn } from "./presets.js";
import { centreUncovered } from "./stageProbes.js";
import { forEachWindowSize, withWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** Loads a preset and waits until its body `id` is in the Bodies table at t = 0. */
const loadPreset = (title: string, id: string) => loadPresetOn(editor.page, title, id);

describe("messages and small windows", () => {
  it("a message, however long, never moves the canvas; a long one hangs over the side column, whole after More, and can be dismissed", async () => {
    await withWindowSize(editor.page, 1280, 800, async () => {
      const canvasTop = async () => (await editor.page.getByTestId("scene-canvas").boundingBox())!.y;
      await showMessage(editor.page, null);
      const before = await canvasTop();
      await showMessage(editor.page, "short");
      expect(await canvasTop()).toBe(before);
      await showMessage(editor.page, longRefusal(8));
      const alert = editor.page.getByRole("alert");
      await poll(async () => (await alert.textContent())?.includes("end")).toBe(true);
      expect(await canvasTop()).toBe(before);
      // at 1280 px it hangs under the header over the side column, cut to one line there (it covers
      // the Calculation panel's heading, not its fields): More shows it whole, on its lines
      expect((await alert.boundingBox())!.height).toBeLessThan(40);
      await editor.page.getByRole("button", { name: "More" }).click();
      expect((await alert.boundingBox())!.height).toBeGreaterThan(40);
      expect(await canvasTop()).toBe(before);
      // its ✕ is on top and works
      await screenshot(editor.page, "14-long-message");
      const dismiss = editor.page.getByRole("button", { name: "Dismiss message" });
      expect(await centreUncovered(dismiss)).toBe(true);
      await dismiss.click();
      await poll(() => alert.count()).toBe(0);
      expect(await canvasTop()).toBe(before);
    });
  });

  it("in an 800 x 600 window a long message keeps to its line in the header: the toolbar stays usable", async () => {
    await withWindowSize(editor.page, 800, 600, async () => {
      await showMessage(editor.page, longRefusal(4));
      await poll(async () => (await editor.page.getByRole("alert").textContent())?.includes("end")).toBe(
        true,
      );
      const canvasTop = (await editor.page.getByTestId("scene-canvas").boundingBox())!.y;
      await editor.page.getByRole("button", { name: "More" }).waitFor();
      expect((await editor.page.getByRole("alert").boundingBox())!.height).toBeLessThanOrEqual(30);
      for (const name of ["Fit", "Delete", "Point", "More"]) {
        // the toolbar's Delete names what it removes ("Delete: body b1") when something is selected
        const button =
          name === "Delete"
            ? editor.page
                .getByRole("toolbar", { name: "Tools" })
                .getByRole("button", { name: /^Delete(: |$)/ })
            : editor.page.getByRole("button", { name, exact: true });
        expect(await centreUncovered(button), `${name} is not covered`).toBe(true);
      }
      await editor.page.getByRole("button", { name: "Dismiss message" }).click();
      expect((await editor.page.getByTestId("scene-canvas").boundingBox())!.y).toBe(canvasTop);
    });
  });

  it("small windows keep the canvas, the Time slider and every time and speed control usable; nothing overflows sideways", async () => {
    await loadPreset("Billiards break", "ball15");
    await forEachWindowSize(
      editor.page,
      [
        [1024, 700],
        [800, 600],
        [390, 844],
      ],
      async (width, height) => {
        // the scene is fitted again to the smaller canvas (the view was never moved by hand)
        await poll(() => bodiesOutsideCanvas()).toBe(0);
        // no sideways scrolling (at 390 px the Speed panel was once 4 px too wide)
        expect(await editor.page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(
          width,
        );
        const canvas = (await editor.page.getByTestId("scene-canvas").boundingBox())!;
        expect(canvas.width).toBeGreaterThanOrEqual(300);
        expect(canvas.height).toBeGreaterThanOrEqual(200);
        const slider = (await editor.page.getByRole("slider", { name: "Time" }).boundingBox())!;
        expect(slider.width).toBeGreaterThanOrEqual(250);
        for (const name of [
          "−1 s: back 1 second",
          "Previous event",
          "Next event",
          "−1×: play backwards",
          "Play",
          "+0.1: faster",
        ]) {
          const button = editor.page.getByRole("button", { name, exact: true });
          await button.scrollIntoViewIfNeeded();
          const box = (await button.boundingBox())!;
          expect(box.x).toBeGreaterThanOrEqual(0);
          expect(box.x + box.width).toBeLessThanOrEqual(width);
          // nothing covers it and it is not squeezed onto several lines
          expect(box.height).toBeLessThan(30);
          expect(await centreUncovered(button)).toBe(true);
        }
        // nor with the longest header (Galperin's digits field shown next to the presets list)
        const presets = editor.page.getByRole("combobox", { name: "Preset" });
        const chosen = await presets.inputValue();
        await presets.selectOption("galperin");
        expect(await editor.page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(
          width,
        );
        await presets.selectOption(chosen);
        await editor.page.evaluate(() => window.scrollTo(0, 0));
        await screenshot(editor.page, `13-window-${width}x${height}`);
      },
    );
  });
});

describe("the Time slider in a stacked window", () => {
  it("from 700 to 900 px it widens with the window: Speed does not squeeze it (it was 766 px at 800, 412 at 850)", async () => {
    let last = 0;
    const widths = Array.from({ length: 9 }, (_, i) => [700 + 25 * i, 700] as const); // 700 to 900 px
    await forEachWindowSize(editor.page, widths, async (width) => {
      const slider = () => editor.page.getByRole("slider", { name: "Time" }).boundingBox();
      await poll(async () => (await slider())!.width).toBeGreaterThan(last);
      const now = (await slider())!.width;
      // the whole line but the panel's and the bar's margins
      expect(now, `${width} px`).toBeGreaterThanOrEqual(width - 50);
      last = now;
    });
    await screenshot(editor.page, "13-window-900-time-bar");
  });
});

/** How many discs the canvas draws (wholly or partly) outside its own box at the current view. */
function bodiesOutsideCanvas(): Promise<number> {
  return editor.page.evaluate(() => {
    type Editor = {
      ui: { getState(): { view: { cx: number; cy: number; scale: number } } };
      client: { latestFrame: { ids: string[]; data: Float64Array } | null };
    };
    const ed = (window as unknown as { chapgame: Editor }).chapgame;
    const f = ed.client.latestFrame;
    if (!f) return -1;
    const { cx, cy, scale } = ed.ui.getState().view;
    const r = document.querySelector("canvas")!.getBoundingClientRect();
    let out = 0;
    for (let i = 0; i < f.ids.length; i++) {
      const x = f.data[i * 11]!;
      const y = f.data[i * 11 + 1]!;
      const rad = f.data[i * 11 + 6]!;
      const sx = r.width / 2 + (x - cx) * scale;
      const sy = r.height / 2 - (y - cy) * scale;
      const sr = rad * scale;
      if (sx - sr < 0 || sy - sr < 0 || sx + sr > r.width || sy + sr > r.height) out++;
    }
    return out;
  });
}
