/**
 * End-to-end, in Debian's Chromium: the persistent notices (newer work saved in another tab, this
 * tab's autosaved scene refused at start) never move the stage (its toolbar, canvas and time bar):
 * one or both at once, they hang over the top of the canvas under the toolbar, whose buttons stay
 * usable as theirs do, at 700, 1280 and 1600 px. Each took a header line of its own, moving the
 * stage down 39 px or more at every width.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { newerNotice, refusedNotice, setNotices as showNotices } from "./notices.js";
import { buttonUncovered, stageBoxes as probeStageBoxes } from "./stageProbes.js";
import { forEachWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** The stage's and the canvas's boxes in the page, as one string to compare ("x y width height" each). */
const stageBoxes = () => probeStageBoxes(editor.page);

/** Shows (or with false takes down) the notices as the editor does (autosave.ts, boot.ts). */
const setNotices = (newer: boolean, refused: boolean) => showNotices(editor.page, newer, refused);

const NEWER = () => newerNotice(editor.page);
const REFUSED = () => refusedNotice(editor.page);

/** Whether the button's centre is in the window and the button itself is there (nothing covers it). */
const uncovered = (name: string, within?: ReturnType<typeof NEWER>) =>
  buttonUncovered(within ?? editor.page, name);

/** The bottom of the stage's toolbar and the top of the highest notice (Infinity: none). */
function toolbarAndNotices(): Promise<[number, number]> {
  return editor.page.evaluate(() => {
    const toolbar = document.querySelector(".toolbar")!.getBoundingClientRect();
    const tops = Array.from(document.querySelectorAll(".stage-notices > *")).map(
      (n) => n.getBoundingClientRect().top,
    );
    return [toolbar.bottom, Math.min(Infinity, ...tops)];
  });
}

describe("the persistent notices", () => {
  it("at 700, 1280 and 1600 px they hang over the canvas under the toolbar: the stage never moves, every button stays usable", async () => {
    try {
      await forEachWindowSize(
        editor.page,
        [
          [700, 800],
          [1280, 800],
          [1600, 900],
        ],
        async (width, height) => {
          const at = `${width} x ${height}`;
          await setNotices(false, false);
          await poll(() => NEWER().count()).toBe(0);
          const before = await stageBoxes();
          for (const [newer, refused, name] of [
            [true, false, "newer"],
            [false, true, "refused"],
            [true, true, "both"],
          ] as const) {
            await setNotices(newer, refused);
            await poll(async () => (await NEWER().count()) + (await REFUSED().count())).toBe(
              Number(newer) + Number(refused),
            );
            expect(await stageBoxes(), `${at}: ${name}`).toBe(before);
            const [toolbarBottom, noticeTop] = await toolbarAndNotices();
            expect(noticeTop, `${at}: ${name} under the toolbar`).toBeGreaterThanOrEqual(toolbarBottom);
            for (const tool of ["Move", "Point", "Fit", "Keyboard shortcuts"])
              expect(await uncovered(tool), `${at}: ${name}, ${tool}`).toBe(true);
            if (newer)
              for (const b of ["Open it", "Dismiss"])
                expect(await uncovered(b, NEWER()), `${at}: ${b}`).toBe(true);
            if (refused)
              for (const b of ["Save it as a file", "Dismiss"])
                expect(await uncovered(b, REFUSED()), `${at}: ${b}`).toBe(true);
            await screenshot(editor.page, `stage-notices-${name}-${width}`);
          }
          // dismissed one after the other, by their own buttons: the stage stays
          await NEWER().getByRole("button", { name: "Dismiss" }).click();
          await poll(() => NEWER().count()).toBe(0);
          expect(await stageBoxes(), `${at}: newer work dismissed`).toBe(before);
          await REFUSED().getByRole("button", { name: "Dismiss" }).click();
          await poll(() => REFUSED().count()).toBe(0);
          expect(await stageBoxes(), `${at}: refused scene dismissed`).toBe(before);
        },
      );
    } finally {
      await setNotices(false, false);
    }
  });
});
