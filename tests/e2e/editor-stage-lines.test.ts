/**
 * End-to-end, in Debian's Chromium: the stage's toolbar and time bar keep their lines from 901 to
 * 1920 px (two columns). The toolbar is one line (33 px high) at every width there, every control on
 * it in view, uncovered and at least 24 px wide, Velocity and Segment named by their whole word
 * wherever they show a short label: from 901 to 1279 px Delete and ? wrapped onto a second line of
 * their own (below 1001 px Trails and Path too; 58 px, 25 px of canvas lost). The time bar is as
 * high at 901 to 1099 px as at 1400 px (180): the Time panel's zoom controls took a line of their
 * own there (207 px). A field's refusal shown in the message over the side column (1027 to 1382 px)
 * leaves that field uncovered: on two lines it hid the top of Seconds ahead, the field the user was
 * correcting. Path's note ("select a body") keeps the toolbar one line: beside Path it wrapped the
 * toolbar from 901 to 1280 px (57 px high); it hangs over the canvas under the toolbar and any
 * notice, and lets the pointer through to the canvas.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { showMessage } from "./messages.js";
import { setNotices } from "./notices.js";
import { buttonUncovered } from "./stageProbes.js";
import { forEachWindowSize, TWO_COLUMN_WINDOWS, type WindowSize, withWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** The widths where a message can hang over the side column (900 px high). */
const REFUSAL_SIZES: WindowSize[] = [1027, 1100, 1200, 1382].map((w) => [w, 900] as const);

/** The window sizes measured: 900 px high, 1080 for 1920 px. */
const SIZES = TWO_COLUMN_WINDOWS;

/** The toolbar's and the time bar's heights, and each toolbar control's name, top and width. */
function stageLines() {
  return editor.page.evaluate(() => {
    const height = (sel: string) => document.querySelector(sel)!.getBoundingClientRect().height;
    const controls = Array.from(document.querySelectorAll(".toolbar > button, .toolbar > label")).map(
      (el) => {
        const r = el.getBoundingClientRect();
        const name = el.getAttribute("aria-label") ?? el.textContent!.trim();
        return { name, top: r.top, width: r.width, tag: el.tagName };
      },
    );
    return { toolbar: height(".toolbar"), timebar: height(".timebar"), controls };
  });
}

describe("the stage's lines from 901 to 1920 px", () => {
  it("the toolbar is one line, its controls in view, uncovered and at least 24 px wide", async () => {
    const wide = await withWindowSize(editor.page, 1400, 900, stageLines);
    await forEachWindowSize(editor.page, SIZES, async (width, height) => {
      const at = `${width} x ${height}`;
      const l = await stageLines();
      expect(l.controls.length, at).toBe(13);
      const tops = l.controls.map((c) => c.top);
      expect(Math.max(...tops) - Math.min(...tops), `${at}: ${JSON.stringify(l.controls)}`).toBeLessThan(4);
      expect(l.toolbar, at).toBe(wide.toolbar);
      for (const c of l.controls) {
        if (c.tag === "BUTTON") {
          expect(c.width, `${at}: ${c.name}`).toBeGreaterThanOrEqual(24);
          expect(await buttonUncovered(editor.page, c.name), `${at}: ${c.name}`).toBe(true);
        }
      }
      // the short labels keep the whole word as the button's name
      for (const name of ["Velocity", "Segment"])
        await expect(editor.page.getByRole("button", { name, exact: true }).isVisible(), at).resolves.toBe(
          true,
        );
      await screenshot(editor.page, `stage-lines-${width}`);
    });
  });

  it("Path's note keeps the toolbar one line, hanging under it and any notice over the canvas", async () => {
    const wide = await withWindowSize(editor.page, 1400, 900, stageLines);
    const pathBox = editor.page.getByRole("checkbox", { name: "Path" });
    const note = editor.page.getByText("select a body", { exact: true });
    await editor.page.evaluate(() => {
      type Ui = { ui: { setState(s: Record<string, unknown>): void } };
      (window as unknown as { chapgame: Ui }).chapgame.ui.setState({ selection: null });
    });
    await pathBox.check();
    try {
      await forEachWindowSize(editor.page, SIZES, async (width, height) => {
        for (const notices of [false, true]) {
          const at = `${width} x ${height}${notices ? ", with the notices" : ""}`;
          await setNotices(editor.page, notices, notices);
          await note.waitFor();
          const l = await stageLines();
          const tops = l.controls.map((c) => c.top);
          expect(Math.max(...tops) - Math.min(...tops), `${at}: toolbar tops`).toBeLessThan(4);
          expect(l.toolbar, at).toBe(wide.toolbar);
          const n = (await note.boundingBox())!;
          const toolbar = (await editor.page.getByRole("toolbar", { name: "Tools" }).boundingBox())!;
          const canvas = (await editor.page.getByTestId("scene-canvas").boundingBox())!;
          const noticesEnd = await editor.page.evaluate(() =>
            Math.max(
              0,
              ...Array.from(document.querySelectorAll(".stage-notices > *")).map(
                (e) => e.getBoundingClientRect().bottom,
              ),
            ),
          );
          expect(n.y, `${at}: under the toolbar`).toBeGreaterThanOrEqual(toolbar.y + toolbar.height);
          expect(n.y, `${at}: under the notices`).toBeGreaterThanOrEqual(noticesEnd);
          expect(n.x + n.width, `${at}: within the canvas`).toBeLessThanOrEqual(canvas.x + canvas.width);
          // the canvas is what a pointer meets there
          const through = await note.evaluate((el) => {
            const r = el.getBoundingClientRect();
            return document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2)?.tagName;
          });
          expect(through, at).toBe("CANVAS");
          if (notices) await screenshot(editor.page, `stage-lines-path-note-${width}`);
        }
        await setNotices(editor.page, false, false);
      });
    } finally {
      await setNotices(editor.page, false, false);
      await pathBox.uncheck();
    }
  });

  it("the time bar is as high as at 1400 px, its controls in view", async () => {
    const wide = await withWindowSize(editor.page, 1400, 900, stageLines);
    await forEachWindowSize(editor.page, SIZES, async (width, height) => {
      const at = `${width} x ${height}`;
      expect((await stageLines()).timebar, at).toBe(wide.timebar);
      for (const name of ["Zoom in", "Whole history", "Next event", "Play"])
        expect(await buttonUncovered(editor.page, name), `${at}: ${name}`).toBe(true);
    });
  });

  it("a field's refusal over the side column leaves that field uncovered; More shows it whole", async () => {
    const field = editor.page.getByRole("textbox", { name: "Seconds ahead", exact: true });
    try {
      await forEachWindowSize(editor.page, REFUSAL_SIZES, async (width) => {
        const at = `${width} px`;
        await field.fill(`-${width}`);
        await field.press("Enter");
        const message = editor.page.getByRole("alert");
        await poll(() => message.textContent()).toContain(`(got -${width})`);
        const m = (await message.boundingBox())!;
        const f = (await field.boundingBox())!;
        const side = (await editor.page.locator(".side").boundingBox())!;
        // the case this is about: the message hangs over the side column
        expect(m.x, `${at}: over the side column`).toBeGreaterThanOrEqual(side.x);
        expect(m.y + m.height, `${at}: the message's bottom above the field's top`).toBeLessThanOrEqual(f.y);
        // cut to its line where it is longer (always at 1027 px: the side column is 410 px), More
        // then shows it whole; where it fits (1382 px) there is no More
        const cut = await message.locator("span").evaluate((el) => el.scrollWidth > el.clientWidth + 1);
        if (width === 1027) expect(cut, at).toBe(true);
        const more = editor.page.getByRole("button", { name: "More" });
        await poll(() => more.count()).toBe(cut ? 1 : 0);
        if (cut) {
          await more.click();
          const whole = (await message.boundingBox())!;
          expect(whole.height, `${at}: More shows it on more lines`).toBeGreaterThan(m.height);
        }
        await editor.page.getByRole("button", { name: "Dismiss message" }).click();
      });
    } finally {
      await field.fill("10");
      await field.press("Enter");
      await showMessage(editor.page, null);
    }
  });
});
