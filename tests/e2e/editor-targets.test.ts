/**
 * End-to-end, in Debian's Chromium: every target of the stage, the header, the message bar, the
 * persistent notices, the side panels out of their tables and the Keyboard shortcuts dialog is at
 * least 24 x 24 px (WCAG 2.2, 2.5.8) at every window size the editor's end-to-end tests use, and no
 * two of them overlap: the stage's toolbar and time bar (Time and Speed), their buttons and text
 * fields, with the toolbar's checkbox labels (Trails, Path); the header's Undo, Redo, Save file,
 * Load file, scene title, preset list and Load preset; the message's More / Less and ✕; the notices'
 * More / Less, Open it, Dismiss and Save it as a file, cut to their line and shown whole; the side
 * panels' buttons, fields and labels, and the dialog's Close and checkbox. They were 21 px high at
 * every width (13 px text, 2 px padding), ? 21 px wide and the time bar's 0 button 22 in a short
 * window, the labels and the preset list 19 px high, the message's and the notices' buttons 17 (21
 * in a short window's notices), the Globals values 17 (19.5 px wide). The Time slider (16 px high)
 * is kept smaller, by WCAG's spacing exception, which is checked for it instead. The tables' targets
 * (a cell's value, a row's Delete, the Event log's ✕) are editor-targets-tables'. That none of this
 * cost the canvas a line is editor-stage-lines', editor-short-stage-lines' and editor-header-lines'
 * (the toolbar, the time bar and the header as high as before); that the notices keep to one line
 * in a short window, editor-notices-short's.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { longRefusal, showMessage } from "./messages.js";
import { newerNotice, refusedNotice, setNotices } from "./notices.js";
import { expectTargets, names, TARGET_SIZES, type Target, targetsOf } from "./targetBoxes.js";
import { forEachWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** The drawn elements `selector` finds, as targets. */
const targets = (selector: string) => targetsOf(editor.page, selector);

/** The stage's targets: its toolbar's buttons and checkbox labels, its time bar's buttons and text
 *  fields (not the Time slider: expectSpacing checks it). */
const STAGE_TARGETS = ".toolbar button, .toolbar label, .timebar button, .timebar input:not([type=range])";
/** The header's buttons (the message's among them) and fields, and the notices' buttons. */
const BAR_TARGETS = ".header button, .header input, .header select, .stage-notices button";

/**
 * Expects WCAG's spacing for a target under 24 px high spanning a line (the Time slider): a 24 px
 * circle centred on its thumb, wherever the thumb is along it, meets no other target, that is no
 * target's box reaches within 12 px of its middle line from 12 px before its start to 12 px past
 * its end.
 */
function expectSpacing(at: string, slider: Target, others: Target[]): void {
  const middle = slider.y + slider.height / 2;
  const band = { x: slider.x - 12, right: slider.x + slider.width + 12, y: middle - 12, bottom: middle + 12 };
  for (const t of others) {
    const overlapX = Math.min(band.right, t.x + t.width) - Math.max(band.x, t.x);
    const overlapY = Math.min(band.bottom, t.y + t.height) - Math.max(band.y, t.y);
    expect(overlapX > 0 && overlapY > 0, `${at}: ${t.name} within 12 px of ${slider.name}`).toBe(false);
  }
}

/** The buttons drawn at every size while the message and both notices are shown, but More (where
 *  a text is cut): the header's, the message's ✕, and the notices'. */
const BAR_BUTTONS = [
  "Undo",
  "Redo",
  "Save file",
  "Load file",
  "Scene title",
  "Preset",
  "Load preset",
  "Dismiss message",
];
const NOTICE_BUTTONS = ["Open it", "Dismiss", "Save it as a file", "Dismiss"];

describe("the stage's targets", () => {
  it("are at least 24 x 24 px at every window size, none overlapping another; the Time slider keeps WCAG's spacing", async () => {
    await forEachWindowSize(editor.page, TARGET_SIZES, async (width, height) => {
      const at = `${width} x ${height}`;
      const stage = await targets(STAGE_TARGETS);
      // the 8 tools, Fit, Trails, Path, Delete, ?; the zoom's 3, the steps' 5, Speed's 5; the 3 fields
      expect(stage.length, at).toBe(29);
      expectTargets(at, stage);
      // the Time slider, 16 px high, by WCAG's spacing
      const [slider] = await targets(".timebar input[type=range]");
      expect(slider!.name, at).toBe("Time");
      // the canvas is a target too (bodies are pressed and dragged on it): in a short window it ends
      // 12 px above the slider's middle, where the circle only touches it
      const canvas = (await targets("[data-testid=scene-canvas]")).map((t) => ({ ...t, name: "the canvas" }));
      expect(canvas.length, at).toBe(1);
      expectSpacing(at, slider!, [...stage, ...(await targets(BAR_TARGETS)), ...canvas]);
    });
  });
});

describe("the header's, the message's and the notices' targets", () => {
  it("are at least 24 x 24 px at every window size, cut and shown whole, none overlapping another or the stage's", async () => {
    try {
      await forEachWindowSize(editor.page, TARGET_SIZES, async (width, height) => {
        await setNotices(editor.page, true, true);
        await showMessage(editor.page, longRefusal(3));
        await poll(async () => (await targets(BAR_TARGETS)).length).toBeGreaterThanOrEqual(
          BAR_BUTTONS.length + NOTICE_BUTTONS.length,
        );
        const cut = await targets(BAR_TARGETS);
        const shown = names(cut).filter((n) => n !== "More");
        expect(shown.sort(), `${width} x ${height}`).toEqual([...BAR_BUTTONS, ...NOTICE_BUTTONS].sort());
        expectTargets(`${width} x ${height}, cut`, [...cut, ...(await targets(STAGE_TARGETS))]);
        // every More pressed, notices first (an open message may hang over them): each is Less
        const mores = names(cut).filter((n) => n === "More").length;
        for (const scope of [
          refusedNotice(editor.page),
          newerNotice(editor.page),
          editor.page.locator(".message"),
        ]) {
          const more = scope.getByRole("button", { name: "More", exact: true });
          if (await more.isVisible()) await more.click();
        }
        await poll(async () => names(await targets(BAR_TARGETS)).filter((n) => n === "Less").length).toBe(
          mores,
        );
        const whole = await targets(BAR_TARGETS);
        expect(names(whole), `${width} x ${height}`).not.toContain("More");
        expectTargets(`${width} x ${height}, whole`, [...whole, ...(await targets(STAGE_TARGETS))]);
        await showMessage(editor.page, null);
        await setNotices(editor.page, false, false);
      });
    } finally {
      await showMessage(editor.page, null);
      await setNotices(editor.page, false, false);
    }
  });
});

/** The side panels' targets out of the tables (their buttons, text fields and checkbox or radio
 *  labels); not the tables' (a cell's value, a row's Delete, the Event log's ✕: editor-targets-tables
 *  checks them), nor the Event details' participants (links in its text), nor a Skip the … table unfocused. */
const SIDE_TARGETS = [
  ".side button:not(td *, .link, .skip-table)",
  ".side input:not([type=checkbox], [type=radio], td *)",
  ".side label:has(> input:is([type=checkbox], [type=radio]))",
].join(", ");
/** Among them, those of the start scene at every size. */
const SIDE_NAMED = [
  "Seconds ahead",
  "Events ahead",
  "Add body",
  "Add line",
  "Add point",
  "g = 1",
  "g = 9.81",
];

describe("the side panels' and the Keyboard shortcuts dialog's targets out of the tables", () => {
  it("are at least 24 x 24 px at every window size, none overlapping another", async () => {
    await forEachWindowSize(editor.page, TARGET_SIZES, async (width, height) => {
      const at = `${width} x ${height}`;
      const side = await targets(SIDE_TARGETS);
      expect(names(side), at).toEqual(expect.arrayContaining([...SIDE_NAMED, "Share link", "Copy", "Paste"]));
      expectTargets(at, side);
      for (const table of ["Bodies", "Event log"]) {
        await editor.page.getByRole("button", { name: `Skip the ${table} table` }).focus();
        expectTargets(`${at}, focused`, await targets(".side .skip-table:focus"));
      }
      await editor.page.getByRole("button", { name: "Keyboard shortcuts" }).click();
      const dialog = await targets(".modal button, .modal label:has(> input[type=checkbox])");
      expect(names(dialog).length, at).toBe(2); // Close, and the checkbox
      expectTargets(`${at}, dialog`, dialog);
      await editor.page.getByRole("button", { name: "Close" }).click();
    });
  });
});
