/**
 * End-to-end, in Debian's Chromium: no message moves the stage (its toolbar, canvas and time bar),
 * at 700, 900 and 1280 px wide. Every kind is shown and taken down while the stage's and the
 * canvas's boxes are measured: a short refusal, a notice, a long one of several lines, a rename
 * refused in the Bodies table, the digits of π refused (in the message bar and beside the field at
 * once), and the notices of a preset loaded and computed (they change while the worker computes).
 * Up to 1000 px a message once took its lines in the header, moving the stage down by a line or more
 * (at 900 px a refusal of 90 characters by 6 px, a long one by 51 px; at 700 px a refusal of 30).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { longRefusal, showMessage, type Tone } from "./messages.js";
import { centreUncovered, stageBoxes as probeStageBoxes } from "./stageProbes.js";
import { forEachWindowSize, withWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** The stage's and the canvas's boxes in the page (not the window: it scrolls to a table's cell
 *  below the stage), as one string to compare ("x y width height" each). */
const stageBoxes = () => probeStageBoxes(editor.page);

/** Shows `text` in the message bar as the editor does (null: takes the message down). */
const setMessage = (text: string | null, tone: Tone = "error") => showMessage(editor.page, text, tone);

const shownMessage = () => editor.page.locator(".message > span").textContent();
const LONG = longRefusal(6);
const WIDTHS = [
  [700, 800],
  [900, 700],
  [1280, 800],
] as const;

describe("messages never move the stage", () => {
  it("at 700, 900 and 1280 px: refusals, notices, long ones, two at once and those of a computation", async () => {
    try {
      await forEachWindowSize(editor.page, WIDTHS, async (width, height) => {
        await editor.page.getByRole("combobox", { name: "Preset" }).selectOption("originalDemo");
        await setMessage(null);
        const at = `${width} x ${height}`;
        const before = await stageBoxes();
        for (const [text, tone] of [
          ['x: must be a number (got "abc")', "error"],
          ["Loaded the preset. Undo returns to the scene you had.", "info"],
          [LONG, "error"],
        ] as const) {
          await setMessage(text, tone);
          await poll(shownMessage).toBe(text);
          expect(await stageBoxes(), `${at}: ${text.slice(0, 30)}`).toBe(before);
        }
        await screenshot(editor.page, `narrow-message-long-${width}`);
        await editor.page.getByRole("button", { name: "Dismiss message" }).click();
        expect(await stageBoxes(), `${at}: dismissed`).toBe(before);

        // a rename refused in the Bodies table (beside the cell and in the message bar)
        const bodies = editor.page.getByRole("table", { name: "Bodies" });
        await bodies.getByLabel("A id", { exact: true }).click();
        const cell = bodies.getByRole("textbox", { name: "A id", exact: true });
        await cell.fill("B");
        await cell.press("Enter");
        await poll(shownMessage).toBe('A id: must not be the id of another body (got "B")');
        expect(await stageBoxes(), `${at}: rename refused`).toBe(before);
        await screenshot(editor.page, `narrow-message-rename-${width}`);
        await cell.press("Escape");
        await setMessage(null);

        // the digits of π refused: in the message bar and beside its field at once
        await editor.page.getByRole("combobox", { name: "Preset" }).selectOption("galperin");
        await setMessage(null);
        // choosing Galperin's billiard shows its digits field (the header keeps its lines:
        // editor-preset-header.test.ts)
        const galperin = await stageBoxes();
        expect(galperin, `${at}: Galperin chosen`).toBe(before);
        const digits = editor.page.getByRole("spinbutton", { name: "Digits of π" });
        await digits.fill("9");
        await digits.blur();
        await poll(shownMessage).toBe("Digits of π: must be a whole number from 1 to 7 (got 9)");
        expect(await stageBoxes(), `${at}: digits refused`).toBe(galperin);
        await screenshot(editor.page, `narrow-message-digits-${width}`);

        // loaded and computed: its notice changes while the worker computes, the stage stays
        await digits.fill("5");
        await editor.page.getByRole("button", { name: "Load preset" }).click();
        const seen = new Set<string>();
        await poll(async () => {
          seen.add(await stageBoxes());
          return shownMessage();
        }).toMatch(/ 31415 collisions, up to t = /);
        seen.add(await stageBoxes());
        expect([...seen], `${at}: preset loaded and computed`).toEqual([galperin]);
        // back to the sample (its discs A and B) for the next width
        await editor.page.getByRole("button", { name: "Undo", exact: true }).click();
        await bodies.getByLabel("A id", { exact: true }).waitFor();
        await setMessage(null);
      });
    } finally {
      await editor.page.getByRole("combobox", { name: "Preset" }).selectOption("originalDemo");
    }
  });

  it("up to 1000 px a long message keeps to its line, More shows it whole over the stage, Less and ✕ take it back", async () => {
    await withWindowSize(editor.page, 900, 700, async () => {
      await setMessage(null);
      const before = await stageBoxes();
      await setMessage(LONG);
      const alert = editor.page.locator(".message");
      await poll(shownMessage).toBe(LONG);
      const more = editor.page.getByRole("button", { name: "More" });
      await more.waitFor();
      expect(await more.getAttribute("aria-expanded")).toBe("false");
      expect((await alert.boundingBox())!.height).toBeLessThanOrEqual(30);
      const uncovered = (name: string) =>
        centreUncovered(editor.page.getByRole("button", { name, exact: true }));
      for (const name of ["Fit", "Point", "More", "Dismiss message"])
        expect(await uncovered(name), name).toBe(true);
      await more.click();
      const less = editor.page.getByRole("button", { name: "Less" });
      expect(await less.getAttribute("aria-expanded")).toBe("true");
      // whole, over the stage: the stage has not moved
      await poll(async () => (await alert.boundingBox())!.height).toBeGreaterThan(60);
      expect(await stageBoxes()).toBe(before);
      for (const name of ["Less", "Dismiss message"]) expect(await uncovered(name), name).toBe(true);
      await screenshot(editor.page, "narrow-message-more-900");
      await less.click();
      await poll(async () => (await alert.boundingBox())!.height).toBeLessThanOrEqual(30);
      expect(await uncovered("Fit")).toBe(true);
      // the next message is shown on its line first; a short one needs no More
      await more.click();
      await setMessage(`${LONG} again`);
      await poll(() => more.getAttribute("aria-expanded")).toBe("false");
      await setMessage("Short.");
      await poll(() => editor.page.getByRole("button", { name: /^(More|Less)$/ }).count()).toBe(0);
      await editor.page.getByRole("button", { name: "Dismiss message" }).click();
      expect(await stageBoxes()).toBe(before);
    });
  });
});
