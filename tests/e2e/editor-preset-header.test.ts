/**
 * End-to-end, in Debian's Chromium: choosing a preset in the Preset list never changes the header's
 * height nor moves the stage (its toolbar, canvas and time bar), from 390 to 1920 px wide, and
 * nothing overflows sideways with Galperin's digits field shown. At 700 px that field once put the
 * message slot on a line of its own (header 79 -> 116 px, the canvas 37 px lower).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { stageBoxes as probeStageBoxes } from "./stageProbes.js";
import { forEachWindowSize, withWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** The stage's and the canvas's boxes in the page, as one string to compare ("x y width height" each). */
const stageBoxes = () => probeStageBoxes(editor.page);

describe("the Preset list", () => {
  it("choosing any preset keeps the header's height and the stage's box from 390 to 1920 px", async () => {
    const presets = editor.page.getByRole("combobox", { name: "Preset" });
    const ids = await presets
      .locator("option")
      .evaluateAll((os) => os.map((o) => (o as HTMLOptionElement).value));
    expect(ids).toContain("galperin");
    const header = async () => (await editor.page.locator("header.header").boundingBox())!.height;
    try {
      await forEachWindowSize(
        editor.page,
        [
          [390, 844],
          [700, 800],
          [800, 600],
          [1000, 700],
          [1280, 800],
          [1400, 900],
          [1920, 1080],
        ],
        async (width, height) => {
          await presets.selectOption("originalDemo");
          await poll(() => editor.page.getByRole("spinbutton", { name: "Digits of π" }).count()).toBe(0);
          const before = [await header(), await stageBoxes()];
          for (const id of ids) {
            await presets.selectOption(id);
            expect([await header(), await stageBoxes()], `${width} x ${height}: ${id}`).toEqual(before);
          }
          // Galperin's digits field is there, and nothing overflows sideways
          await presets.selectOption("galperin");
          await editor.page.getByRole("spinbutton", { name: "Digits of π" }).waitFor();
          expect(await editor.page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(
            width,
          );
          if (width === 700) await screenshot(editor.page, "preset-header-galperin-700");
        },
      );
      // the header at 700 px is its two lines (the message slot beside the presets), as before Galperin
      await withWindowSize(editor.page, 700, 800, () => poll(header).toBeLessThan(100));
    } finally {
      await presets.selectOption("originalDemo");
    }
  });
});
