/**
 * End-to-end, in Debian's Chromium: messages never move the canvas (a long one hangs over the stage
 * and can be dismissed; at 800 x 600 it keeps to its line in the header and the toolbar stays usable:
 * editor-narrow-messages.test.ts measures the stage for every kind of message at 700 and 900 px),
 * and small windows (1024 x 700 down to 390 x 844) keep the canvas, the Time slider and every time
 * and speed control usable, nothing overflowing sideways; from 700 to 900 px the Time slider widens
 * with the window (Speed goes under Time rather than squeeze it).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { loadPresetOn } from "./presets.js";

const editor = editorForFile();

/** Loads a preset and waits until its body `id` is in the Bodies table at t = 0. */
const loadPreset = (title: string, id: string) => loadPresetOn(editor.page, title, id);

describe("messages and small windows", () => {
  it("a message, however long, never moves the canvas; a long one hangs over the stage and can be dismissed", async () => {
    await editor.page.setViewportSize({ width: 1280, height: 800 });
    try {
      const canvasTop = async () => (await editor.page.getByTestId("scene-canvas").boundingBox())!.y;
      const setMessage = (text: string | null) =>
        editor.page.evaluate((t) => {
          type Ui = { ui: { setState(s: { message: { text: string; tone: "error" } | null }): void } };
          (window as unknown as { chapgame: Ui }).chapgame.ui.setState({
            message: t === null ? null : { text: t, tone: "error" },
          });
        }, text);
      await setMessage(null);
      const before = await canvasTop();
      await setMessage("short");
      expect(await canvasTop()).toBe(before);
      const long = `${"A refused edit whose explanation runs over several lines of the header. ".repeat(8)}end`;
      await setMessage(long);
      const alert = editor.page.getByRole("alert");
      await poll(async () => (await alert.textContent())?.includes("end")).toBe(true);
      expect(await canvasTop()).toBe(before);
      // it hangs below the header's row, over the stage, and its ✕ is on top and works
      expect((await alert.boundingBox())!.height).toBeGreaterThan(40);
      await screenshot(editor.page, "14-long-message");
      const dismiss = editor.page.getByRole("button", { name: "Dismiss message" });
      const onTop = await dismiss.evaluate((el) => {
        const r = el.getBoundingClientRect();
        return el.contains(document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2));
      });
      expect(onTop).toBe(true);
      await dismiss.click();
      await poll(() => alert.count()).toBe(0);
      expect(await canvasTop()).toBe(before);
    } finally {
      await editor.page.setViewportSize({ width: 1400, height: 900 });
    }
  });

  it("in an 800 x 600 window a long message keeps to its line in the header: the toolbar stays usable", async () => {
    await editor.page.setViewportSize({ width: 800, height: 600 });
    try {
      const long = `${"A refused edit whose explanation runs over several lines of the header. ".repeat(4)}end`;
      await editor.page.evaluate((t) => {
        type Ui = { ui: { setState(s: { message: { text: string; tone: "error" } | null }): void } };
        (window as unknown as { chapgame: Ui }).chapgame.ui.setState({ message: { text: t, tone: "error" } });
      }, long);
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
        const reachable = await button.evaluate((el) => {
          const r = el.getBoundingClientRect();
          return el.contains(document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2));
        });
        expect(reachable, `${name} is not covered`).toBe(true);
      }
      await editor.page.getByRole("button", { name: "Dismiss message" }).click();
      expect((await editor.page.getByTestId("scene-canvas").boundingBox())!.y).toBe(canvasTop);
    } finally {
      await editor.page.setViewportSize({ width: 1400, height: 900 });
    }
  });

  it("small windows keep the canvas, the Time slider and every time and speed control usable; nothing overflows sideways", async () => {
    await loadPreset("Billiards break", "ball15");
    try {
      for (const [width, height] of [
        [1024, 700],
        [800, 600],
        [390, 844],
      ] as const) {
        await editor.page.setViewportSize({ width, height });
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
          // the toolbar's Delete names what it removes ("Delete: body b1") when something is selected
          const button =
            name === "Delete"
              ? editor.page
                  .getByRole("toolbar", { name: "Tools" })
                  .getByRole("button", { name: /^Delete(: |$)/ })
              : editor.page.getByRole("button", { name, exact: true });
          await button.scrollIntoViewIfNeeded();
          const box = (await button.boundingBox())!;
          expect(box.x).toBeGreaterThanOrEqual(0);
          expect(box.x + box.width).toBeLessThanOrEqual(width);
          // nothing covers it and it is not squeezed onto several lines
          expect(box.height).toBeLessThan(30);
          const onTop = await button.evaluate((el) => {
            const r = el.getBoundingClientRect();
            return el.contains(document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2));
          });
          expect(onTop).toBe(true);
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
      }
    } finally {
      await editor.page.setViewportSize({ width: 1400, height: 900 });
    }
  });
});

describe("the Time slider in a stacked window", () => {
  it("from 700 to 900 px it widens with the window: Speed does not squeeze it (it was 766 px at 800, 412 at 850)", async () => {
    try {
      let last = 0;
      for (let width = 700; width <= 900; width += 25) {
        await editor.page.setViewportSize({ width, height: 700 });
        const slider = () => editor.page.getByRole("slider", { name: "Time" }).boundingBox();
        await poll(async () => (await slider())!.width).toBeGreaterThan(last);
        const now = (await slider())!.width;
        // the whole line but the panel's and the bar's margins
        expect(now, `${width} px`).toBeGreaterThanOrEqual(width - 50);
        last = now;
      }
      await screenshot(editor.page, "13-window-900-time-bar");
    } finally {
      await editor.page.setViewportSize({ width: 1400, height: 900 });
    }
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
