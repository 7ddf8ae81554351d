/**
 * End-to-end, in Debian's Chromium: a message hanging under the header over the side column (1027 to
 * 1382 px wide, where the header's line leaves the message slot under 240 px) covers none of the
 * column's controls. The column starts under a strip kept for it (useMessageStrip.ts), with or
 * without a message, so a message coming or going moves neither the stage nor the column; More
 * lowers the column by the lines it shows. Over the column's top, the message covered Add body and
 * Skip the Bodies table whenever the column was scrolled to the Bodies panel, and shown whole the
 * table's first rows with it (two rows of Bodies at 1027 and 1100 px, one at 1280 and 1382).
 * Where the message does not hang (1001 px, 1400 px) the column starts right under the header.
 */
import { describe, expect, it } from "vitest";
import { bodyGridScene, openBodyGrid } from "./bodyGridScene.js";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { longRefusal, showMessage } from "./messages.js";
import { stageBoxes } from "./stageProbes.js";
import { forEachWindowSize } from "./windowSize.js";

const editor = editorForFile({
  afterOpen: ({ page }) => openBodyGrid(page, bodyGridScene(30, 6)),
});

const LONG = longRefusal(3);

/** Scrolls the side column so that the Bodies panel's heading is at its top. */
function scrollSideToBodies(): Promise<void> {
  return editor.page.evaluate(() => {
    const side = document.querySelector(".side")!;
    const heading = Array.from(side.querySelectorAll("h2")).find((h) => h.textContent?.startsWith("Bodies"))!;
    side.scrollTop += heading.getBoundingClientRect().top - side.getBoundingClientRect().top - 8;
  });
}

/** The side column's controls and rows in its view that the message covers at their centre, the
 *  column's top and the header's foot (px). */
function sideUnderMessage() {
  return editor.page.evaluate(() => {
    const side = document.querySelector(".side")!;
    const s = side.getBoundingClientRect();
    const covered: string[] = [];
    for (const c of Array.from(side.querySelectorAll("button, input, select, tbody tr:not(.spacer)"))) {
      const r = c.getBoundingClientRect();
      const y = r.top + r.height / 2;
      if (r.height === 0 || y < s.top || y > s.bottom) continue;
      const hit = document.elementFromPoint(r.left + Math.min(r.width / 2, 12), y);
      if (hit?.closest(".message")) covered.push(c.getAttribute("aria-label") || c.textContent!.slice(0, 20));
    }
    return {
      covered,
      sideTop: s.top,
      headerFoot: document.querySelector("header.header")!.getBoundingClientRect().bottom,
    };
  });
}

describe("a message hanging over the side column", () => {
  it("from 1027 to 1382 px covers none of the column's controls, one line or whole, and moves neither the stage nor the column", async () => {
    try {
      await forEachWindowSize(
        editor.page,
        [1027, 1100, 1280, 1382].map((width) => [width, 900] as const),
        async (width) => {
          const at = `${width} px`;
          await showMessage(editor.page, null);
          await scrollSideToBodies();
          const stage = await stageBoxes(editor.page);
          const bare = await sideUnderMessage();
          await showMessage(editor.page, LONG);
          const message = editor.page.getByRole("alert");
          await poll(() => message.textContent()).toContain("end");
          // hanging under the header (not on its line)
          expect((await message.boundingBox())!.y, at).toBeGreaterThanOrEqual(bare.headerFoot);
          const shown = await sideUnderMessage();
          expect(shown.covered, `${at}: covered by the message`).toEqual([]);
          expect(shown.sideTop, `${at}: the column did not move`).toBe(bare.sideTop);
          expect(await stageBoxes(editor.page), at).toBe(stage);
          // shown whole (More): the column goes down by its lines, still nothing covered
          await message.getByRole("button", { name: "More" }).click();
          await poll(async () => (await sideUnderMessage()).covered).toEqual([]);
          const whole = (await message.boundingBox())!;
          expect((await sideUnderMessage()).sideTop, at).toBeGreaterThanOrEqual(whole.y + whole.height);
          expect(await stageBoxes(editor.page), `${at}: whole`).toBe(stage);
          await screenshot(editor.page, `message-side-${width}`);
          await message.getByRole("button", { name: "Less" }).click();
          await poll(async () => (await sideUnderMessage()).sideTop).toBe(bare.sideTop);
          await editor.page.getByRole("button", { name: "Dismiss message" }).click();
          expect((await sideUnderMessage()).sideTop, `${at}: dismissed`).toBe(bare.sideTop);
        },
      );
    } finally {
      await showMessage(editor.page, null);
    }
  });

  it("where the message does not hang (1001 and 1400 px) the column starts right under the header", async () => {
    await forEachWindowSize(
      editor.page,
      [1001, 1400].map((width) => [width, 900] as const),
      async (width) => {
        const s = await sideUnderMessage();
        expect(s.sideTop, `${width} px`).toBe(s.headerFoot);
      },
    );
  });
});
