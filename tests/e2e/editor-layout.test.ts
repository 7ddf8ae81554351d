/**
 * End-to-end, in Debian's Chromium: the page at the edges of window sizes. On a wide window
 * (1920 x 1080, 2560 x 1440) every panel keeps a panel's width: the Speed panel once stretched
 * 650 px and more across the time bar, its buttons at one end; only the Time panel, whose slider
 * gains from it, takes the rest of the line.
 */
import type { Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { openEditor, type Session, screenshot } from "./harness.js";
import { loadPresetOn } from "./presets.js";

const poll = <T>(fn: () => T | Promise<T>) => expect.poll(fn, { timeout: 15_000, interval: 50 });

let s: Session;
let page: Page;

beforeAll(async () => {
  s = await openEditor();
  page = s.page;
  await loadPresetOn(page, "Billiards break", "ball15");
});

afterAll(async () => {
  await s?.close();
});

/** A panel's box and the extent of its controls (from the first one's left to the last one's right). */
function panelBox(title: string): Promise<{ width: number; left: number; controls: number }> {
  return page.evaluate((t) => {
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

describe("wide windows", () => {
  it("the Speed panel keeps a panel's width and Time takes the rest of the line; the side panels keep their column's", async () => {
    try {
      for (const [width, height] of [
        [1920, 1080],
        [2560, 1440],
      ] as const) {
        await page.setViewportSize({ width, height });
        await poll(async () => (await panelBox("Time")).width).toBeGreaterThan(width / 3);
        const speed = await panelBox("Speed");
        const time = await panelBox("Time");
        // no wider than its controls and a margin, beside Time on the same line
        expect(speed.width, `${width} x ${height}`).toBeLessThanOrEqual(speed.controls + 64);
        expect(speed.left).toBeGreaterThan(time.left + time.width - 1);
        expect(time.width).toBeGreaterThan(2 * speed.width);
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
        await screenshot(page, `layout-wide-${width}x${height}`);
      }
    } finally {
      await page.setViewportSize({ width: 1400, height: 900 });
    }
  });
});
