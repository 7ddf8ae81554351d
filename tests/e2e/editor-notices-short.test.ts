/**
 * End-to-end, in Debian's Chromium: the persistent notices in short landscape windows (900 x 500,
 * 1280 x 480, 700 x 420, and a phone on its side, 667 x 375). One or both shown, the page still fits
 * the window, the canvas keeps at least half its height uncovered (and 90 px), the notices end above
 * its bottom, and the toolbar, the Time slider, Play and the notices' own buttons stay uncovered;
 * each notice keeps to one line, and its More shows it whole (Less takes it back) with the time bar
 * still uncovered. Whole, two notices once left 69 px of a 215 px canvas at 700 x 420 (54 of 185 at
 * 844 x 390).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { newerNotice, noticesBottom, refusedNotice, setNotices } from "./notices.js";
import { buttonUncovered } from "./stageProbes.js";
import { forEachWindowSize } from "./windowSize.js";

const editor = editorForFile();

/** The page's scroll height against the window's, and the stage's scroll height against its own. */
function scrolls(): Promise<{ page: [number, number]; stage: [number, number] }> {
  return editor.page.evaluate(() => {
    const e = document.scrollingElement!;
    const st = document.querySelector("main.stage")!;
    return { page: [e.scrollHeight, e.clientHeight], stage: [st.scrollHeight, st.clientHeight] };
  });
}

/** Whether the Time slider's thumb end and middle are in the window and uncovered. */
function sliderUncovered(): Promise<boolean> {
  return editor.page.getByRole("slider", { name: "Time" }).evaluate((el) => {
    const r = el.getBoundingClientRect();
    const y = r.y + r.height / 2;
    if (r.bottom > window.innerHeight) return false;
    return [r.x + 4, r.x + r.width / 2].every((x) => el.contains(document.elementFromPoint(x, y)));
  });
}

describe("the persistent notices in a short window", () => {
  it("leave half the canvas, the toolbar, the time bar and their own buttons uncovered; More shows one whole", async () => {
    try {
      await forEachWindowSize(
        editor.page,
        [
          [900, 500],
          [1280, 480],
          [700, 420],
          [667, 375],
        ],
        async (width, height) => {
          for (const [newer, refused, name] of [
            [true, false, "newer"],
            [false, true, "refused"],
            [true, true, "both"],
          ] as const) {
            const at = `${width} x ${height}, ${name}`;
            await setNotices(editor.page, newer, refused);
            await poll(
              async () =>
                (await newerNotice(editor.page).count()) + (await refusedNotice(editor.page).count()),
            ).toBe(Number(newer) + Number(refused));
            const sc = await scrolls();
            expect(sc.page[0], `${at}: the editor.page fits`).toBeLessThanOrEqual(sc.page[1]);
            expect(sc.stage[0], `${at}: the stage fits`).toBeLessThanOrEqual(sc.stage[1]);
            const canvas = (await editor.page.getByTestId("scene-canvas").boundingBox())!.height;
            const covered = await noticesBottom(editor.page);
            expect(canvas - covered, `${at}: canvas left`).toBeGreaterThanOrEqual(Math.max(90, canvas / 2));
            for (const tool of ["Move", "Fit", "Keyboard shortcuts", "Play", "Undo"])
              expect(await buttonUncovered(editor.page, tool), `${at}: ${tool}`).toBe(true);
            expect(await sliderUncovered(), `${at}: Time slider`).toBe(true);
            if (newer)
              for (const b of ["Open it", "Dismiss"])
                expect(await buttonUncovered(newerNotice(editor.page), b), `${at}: ${b}`).toBe(true);
            if (refused)
              for (const b of ["Save it as a file", "Dismiss"])
                expect(await buttonUncovered(refusedNotice(editor.page), b), `${at}: ${b}`).toBe(true);
            // each notice on one line: its buttons no higher than one
            for (const b of await editor.page.locator(".stage-notices button").all())
              expect((await b.boundingBox())!.height, `${at}: a button on one line`).toBeLessThan(30);
            await screenshot(editor.page, `notices-short-${name}-${width}x${height}`);
          }
          // both shown: the refused scene's notice, cut, shown whole by More, then back by Less
          const notice = refusedNotice(editor.page);
          const more = notice.getByRole("button", { name: "More" });
          await more.waitFor();
          const text = notice.locator(".notice-text");
          expect(await text.evaluate((el) => el.scrollWidth > el.clientWidth)).toBe(true);
          const oneLine = (await notice.boundingBox())!.height;
          await more.click();
          const less = notice.getByRole("button", { name: "Less" });
          expect(await less.getAttribute("aria-expanded")).toBe("true");
          await poll(async () => (await notice.boundingBox())!.height).toBeGreaterThan(oneLine + 10);
          expect(await text.evaluate((el) => el.scrollWidth <= el.clientWidth)).toBe(true);
          for (const b of ["Less", "Save it as a file", "Dismiss"])
            expect(await buttonUncovered(notice, b), `${width} x ${height} opened: ${b}`).toBe(true);
          expect(await sliderUncovered(), `${width} x ${height} opened: Time slider`).toBe(true);
          expect(await buttonUncovered(editor.page, "Play"), `${width} x ${height} opened: Play`).toBe(true);
          await screenshot(editor.page, `notices-short-more-${width}x${height}`);
          await less.click();
          await poll(async () => (await notice.boundingBox())!.height).toBe(oneLine);
          await setNotices(editor.page, false, false);
        },
      );
    } finally {
      await setNotices(editor.page, false, false);
    }
  });
});
