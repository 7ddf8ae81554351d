/**
 * End-to-end, in Debian's Chromium: the header is its controls and nothing more. From 1000 to 1920 px
 * every line of the header holds a control (the message slot never takes one of its own), so from
 * 1100 px the header is one line and the canvas starts right under it and the stage's toolbar; a
 * message, short or long, still never moves the stage, and where the header's line leaves the slot
 * too narrow (1100 to 1280 px here) it hangs over the top of the side column, not over the stage's
 * toolbar. From 1127 to 1382 px the slot once took a second line, empty: the header was 79 px high,
 * not 42, and the canvas 37 px lower. The digits' refusal beside its field (Galperin's billiard) once
 * took a header line too, moving the stage 42 px at 1001 and 1400 to 1700 px.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { longRefusal, showMessage } from "./messages.js";
import { buttonUncovered, stageBoxes } from "./stageProbes.js";
import { forEachWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** Shows `text` in the message bar as the editor does (null: takes the message down). */
const setMessage = (text: string | null) => showMessage(editor.page, text);

const LONG = longRefusal(6);

/** The header's lines, top to bottom, each as the class names (or tags) of the items on it, and the
 *  boxes of the header, the toolbar, the canvas and the side column (top, bottom, left, right). */
function headerLayout() {
  return editor.page.evaluate(() => {
    const header = document.querySelector("header.header")!;
    const lines = new Map<number, string[]>();
    for (const item of Array.from(header.children)) {
      const r = item.getBoundingClientRect();
      const top = Math.round(r.top + r.height / 2);
      const line = [...lines.keys()].find((t) => Math.abs(t - top) < 8) ?? top;
      lines.set(line, [...(lines.get(line) ?? []), item.className || item.tagName.toLowerCase()]);
    }
    const box = (sel: string) => {
      const r = document.querySelector(sel)!.getBoundingClientRect();
      return { top: r.top, bottom: r.bottom, left: r.left, right: r.right };
    };
    return {
      lines: [...lines.entries()].sort((a, b) => a[0] - b[0]).map(([, items]) => items),
      header: box("header.header"),
      toolbar: box(".toolbar"),
      canvas: box("[data-testid=scene-canvas]"),
      side: box(".side"),
    };
  });
}

describe("the header's lines", () => {
  it("from 1000 to 1920 px every line holds a control; from 1100 px the header is one line and the canvas right under it", async () => {
    await forEachWindowSize(
      editor.page,
      [1000, 1027, 1100, 1200, 1280, 1382, 1399, 1400, 1920].map((width) => [width, 900] as const),
      async (width) => {
        await setMessage(null);
        const at = `${width} px`;
        const l = await headerLayout();
        // the slot shares its line with a control: no line of the header is the empty slot's
        for (const line of l.lines)
          expect(line, `${at}: ${JSON.stringify(l.lines)}`).not.toEqual(["message-slot"]);
        if (width >= 1100) {
          expect(l.lines.length, `${at}: ${JSON.stringify(l.lines)}`).toBe(1);
          expect(l.header.bottom - l.header.top, at).toBeLessThanOrEqual(45);
        }
        // the stage starts under the header, the canvas under the toolbar: no gap lost between
        expect(l.toolbar.top, at).toBe(l.header.bottom);
        expect(l.canvas.top, at).toBe(l.toolbar.bottom);
        await screenshot(editor.page, `header-lines-${width}`);
      },
    );
  });

  it("a message, short or long, never moves the stage; where the slot is narrow it hangs over the side column, not the toolbar", async () => {
    try {
      await forEachWindowSize(
        editor.page,
        [1001, 1100, 1200, 1280, 1399, 1400, 1920].map((width) => [width, 900] as const),
        async (width) => {
          await setMessage(null);
          const at = `${width} px`;
          const before = await stageBoxes(editor.page);
          const l = await headerLayout();
          for (const text of ['x: must be a number (got "abc")', LONG]) {
            await setMessage(text);
            const message = editor.page.getByRole("alert");
            await poll(() => message.textContent()).toContain(text.slice(-3));
            expect(await stageBoxes(editor.page), `${at}: ${text.slice(0, 20)}`).toBe(before);
            expect(await buttonUncovered(editor.page, "Dismiss message"), `${at}: ✕`).toBe(true);
            const m = (await message.boundingBox())!;
            expect(m.x + m.width, at).toBeLessThanOrEqual(width);
            // on the header's line (a long one hangs down from it), or under the header over the side
            // column, never over the stage; a short one, or one over the side column, leaves every
            // tool uncovered (up to 1026 px the slot is on the presets' line, over the stage's right)
            if (m.y >= l.header.bottom)
              expect(m.x, `${at}: under the header, over the side column`).toBeGreaterThanOrEqual(
                l.side.left,
              );
            if (text !== LONG || m.x >= l.side.left)
              for (const name of ["Move", "Point", "Fit", "Keyboard shortcuts"])
                expect(await buttonUncovered(editor.page, name), `${at}: ${name}`).toBe(true);
          }
          await screenshot(editor.page, `header-lines-message-${width}`);
          await editor.page.getByRole("button", { name: "Dismiss message" }).click();
          expect(await stageBoxes(editor.page), `${at}: dismissed`).toBe(before);
        },
      );
    } finally {
      await setMessage(null);
    }
  });

  it("the digits of π refused never move the stage (the refusal beside the field took a header line)", async () => {
    const presets = editor.page.getByRole("combobox", { name: "Preset" });
    const digits = editor.page.getByRole("spinbutton", { name: "Digits of π" });
    try {
      await forEachWindowSize(
        editor.page,
        [1001, 1200, 1400, 1600, 1920].map((width) => [width, 900] as const),
        async (width) => {
          await presets.selectOption("galperin");
          await digits.fill("4");
          await digits.blur();
          await setMessage(null);
          const before = await stageBoxes(editor.page);
          await digits.fill("9");
          await digits.blur();
          await poll(() => editor.page.getByRole("alert").textContent()).toContain("(got 9)");
          expect(await stageBoxes(editor.page), `${width} px`).toBe(before);
          // the field is marked and described by the refusal (for screen readers)
          expect(await digits.getAttribute("aria-invalid")).toBe("true");
          expect(await digits.getAttribute("title")).toContain("(got 9)");
        },
      );
    } finally {
      await digits.fill("4");
      await digits.blur();
      await presets.selectOption("originalDemo");
      await setMessage(null);
    }
  });
});
