/**
 * End-to-end, in Debian's Chromium: the page at the edges of window sizes. On a wide window
 * (1920 x 1080, 2560 x 1440) every panel keeps a panel's width: the Speed panel once stretched
 * 650 px and more across the time bar, its buttons at one end; only the Time panel, whose slider
 * gains from it, takes the rest of the line. From 1280 to 1920 px the Time slider spans the stage
 * (Speed under Time): beside Time, Speed squeezed it to 407 px at 1400, 582 at 1600, 902 at 1920. On a phone on its side (844 x 390, 740 x 360, 667 x 375)
 * the page fits the window and never scrolls, nor does the stage inside itself: the canvas shrinks,
 * the time bar stays in view and the side panels scroll inside their column (the page once scrolled
 * to 1,584 px, the time bar half below the fold; at 667 x 375 the stage scrolled 32 px inside itself,
 * its canvas 96 px high).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { LOAD_NOTICE, showMessage } from "./messages.js";
import { loadPresetOn } from "./presets.js";
import { buttonUncovered } from "./stageProbes.js";
import { forEachWindowSize } from "./windowSize.js";

const editor = editorForFile({
  afterOpen: (session) => loadPresetOn(session.page, "Billiards break", "ball15"),
});

/** A panel's box and the extent of its controls (from the first one's left to the last one's right). */
function panelBox(title: string): Promise<{ width: number; left: number; controls: number }> {
  return editor.page.evaluate((t) => {
    const panel = Array.from(document.querySelectorAll<HTMLElement>(".panel")).find(
      (p) => p.querySelector("h2")?.textContent?.trim().startsWith(t) === true,
    )!;
    const r = panel.getBoundingClientRect();
    const controls = Array.from(panel.querySelectorAll("button, input, select, label")).map((e) =>
      e.getBoundingClientRect(),
    );
    const from = Math.min(...controls.map((c) => c.left));
    const to = Math.max(...controls.map((c) => c.right));
    return { width: r.width, left: r.left, controls: to - from };
  }, title);
}

/** Whether the element's centre is in the window and the element itself is there (nothing covers it). */
const inView = (name: string) => buttonUncovered(editor.page, name);

/** The stage's (toolbar, canvas, time bar) scroll height and client height. */
function stageScroll(): Promise<[number, number]> {
  return editor.page.locator(".stage").evaluate((el) => [el.scrollHeight, el.clientHeight]);
}

/** The page's scroll sizes and client sizes ([scrollWidth, scrollHeight], [clientWidth, clientHeight]). */
function pageScroll(): Promise<[number[], number[]]> {
  return editor.page.evaluate(() => {
    const e = document.scrollingElement!;
    return [
      [e.scrollWidth, e.scrollHeight],
      [e.clientWidth, e.clientHeight],
    ];
  });
}

describe("wide windows", () => {
  it("the Speed panel keeps a panel's width and Time takes the rest of the line; the side panels keep their column's", async () => {
    await forEachWindowSize(
      editor.page,
      [
        [1920, 1080],
        [2560, 1440],
      ],
      async (width, height) => {
        await poll(async () => (await panelBox("Time")).width).toBeGreaterThan(width / 3);
        const speed = await panelBox("Speed");
        const time = await panelBox("Time");
        // no wider than its controls and a margin; beside Time only where Time keeps three quarters
        // of the line (2560 px), else under it
        expect(speed.width, `${width} x ${height}`).toBeLessThanOrEqual(speed.controls + 64);
        if (width === 2560) {
          expect(speed.left).toBeGreaterThan(time.left + time.width - 1);
          expect(time.width).toBeGreaterThan(3 * speed.width);
        } else expect(speed.left).toBe(time.left);
        for (const title of [
          "Calculation",
          "Bodies",
          "Lines",
          "Points",
          "Globals",
          "Event log",
          "Stats",
          "State",
        ])
          expect((await panelBox(title)).width, title).toBeLessThanOrEqual(560);
        await screenshot(editor.page, `layout-wide-${width}x${height}`);
      },
    );
  });
});

describe("the Time slider in a wide window", () => {
  it("from 1280 to 1920 px it spans the stage, Speed under Time, and nothing overflows", async () => {
    let last = 0;
    await forEachWindowSize(
      editor.page,
      [1280, 1400, 1600, 1760, 1920].map((width) => [width, 900] as const),
      async (width) => {
        const slider = async () =>
          (await editor.page.getByRole("slider", { name: "Time" }).boundingBox())!.width;
        await poll(slider).toBeGreaterThan(last);
        const now = await slider();
        const stage = (await editor.page.locator("main.stage").boundingBox())!;
        // the stage's whole width but the panel's and the bar's margins; the side column takes 40 %
        // of the window up to 1400 px (560 px wider), so that is 57 % of the window there, 69 % at 1920
        expect(now, `${width} px`).toBeGreaterThanOrEqual(stage.width - 40);
        expect(now, `${width} px`).toBeGreaterThanOrEqual(0.55 * width);
        const speed = await panelBox("Speed");
        const time = await panelBox("Time");
        expect(speed.left, `${width} px: Speed under Time`).toBe(time.left);
        // nothing overflows: no sideways scrolling, the stage's panels and buttons inside the stage
        expect((await pageScroll())[0][0]).toBeLessThanOrEqual(width);
        const outside = await editor.page.evaluate(() => {
          const r = document.querySelector("main.stage")!.getBoundingClientRect();
          return Array.from(
            document.querySelectorAll("main.stage .panel, main.stage button, main.stage input"),
          )
            .map((e) => e.getBoundingClientRect())
            .filter((b) => b.left < r.left - 0.5 || b.right > r.right + 0.5).length;
        });
        expect(outside, `${width} px`).toBe(0);
        for (const name of ["Play", "Next event", "+0.1: faster"])
          expect(await inView(name), name).toBe(true);
        last = now;
        await screenshot(editor.page, `layout-time-slider-${width}`);
      },
    );
  });
});

describe("a phone on its side", () => {
  it("the page fits the window, the stage without scrolling inside itself: the canvas shrinks, the time bar is in view, the side panels scroll inside their column", async () => {
    await forEachWindowSize(
      editor.page,
      [
        [844, 390],
        [740, 360],
        [667, 375],
      ],
      async (width, height) => {
        const at = `${width} x ${height}`;
        await poll(pageScroll).toEqual([
          [width, height],
          [width, height],
        ]);
        const [scrollHeight, clientHeight] = await stageScroll();
        expect(scrollHeight, at).toBeLessThanOrEqual(clientHeight);
        const canvas = (await editor.page.getByTestId("scene-canvas").boundingBox())!;
        expect(canvas.height, at).toBeGreaterThanOrEqual(150);
        expect(canvas.width, at).toBeGreaterThanOrEqual(400);
        // zoomed, the Time panel says which part of the history it shows: still no inner scroll
        await editor.page.getByRole("button", { name: "Zoom in", exact: true }).click();
        await editor.page.getByLabel("Time range shown").waitFor();
        const [zoomedScroll, zoomedClient] = await stageScroll();
        expect(zoomedScroll, `${at}, zoomed`).toBeLessThanOrEqual(zoomedClient);
        expect((await editor.page.getByTestId("scene-canvas").boundingBox())!.height).toBeGreaterThanOrEqual(
          120,
        );
        await editor.page.getByRole("button", { name: "Whole history", exact: true }).click();
        const slider = (await editor.page.getByRole("slider", { name: "Time" }).boundingBox())!;
        expect(slider.y + slider.height, at).toBeLessThanOrEqual(height);
        for (const name of ["Play", "Next event", "Previous event", "Undo", "Fit"])
          expect(await inView(name), `${name} at ${at}`).toBe(true);
        // the last panel is reached by scrolling the side column, not the page
        const side = editor.page.locator(".side");
        expect(await side.evaluate((el) => el.scrollHeight > el.clientHeight)).toBe(true);
        await editor.page.getByRole("button", { name: "Share link" }).scrollIntoViewIfNeeded();
        expect(await inView("Share link"), at).toBe(true);
        expect(await side.evaluate((el) => el.scrollTop)).toBeGreaterThan(0);
        expect(await pageScroll()).toEqual([
          [width, height],
          [width, height],
        ]);
        // a message takes its lines above the side panels: the page still fits
        await showMessage(editor.page, LOAD_NOTICE, "info");
        await poll(() => editor.page.getByRole("status").filter({ hasText: "Undo returns" }).count()).toBe(1);
        expect(await pageScroll()).toEqual([
          [width, height],
          [width, height],
        ]);
        expect(await inView("Play"), at).toBe(true);
        await screenshot(editor.page, `layout-landscape-${width}x${height}`);
        await editor.page.getByRole("button", { name: "Dismiss message" }).click();
        await side.evaluate((el) => {
          el.scrollTop = 0;
        });
      },
    );
  });
});
