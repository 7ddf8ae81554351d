/**
 * End-to-end: what the panels and the canvas show a scene author, in Debian's Chromium: the Event
 * log keeps the current time in view, and the layout stays usable in small windows.
 */
import type { Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { openEditor, type Session, screenshot, scrubTo, waitFor } from "./harness.js";

const poll = <T>(fn: () => T | Promise<T>) => expect.poll(fn, { timeout: 15_000, interval: 50 });

let s: Session;
let page: Page;

async function loadPreset(title: string) {
  const select = page.getByRole("combobox", { name: "Preset" });
  const value = await select.locator("option", { hasText: title }).first().getAttribute("value");
  await select.selectOption(value!);
  await page.getByRole("button", { name: "Load preset" }).click();
  await waitFor(async () => Number(await page.getByRole("slider", { name: "Time" }).inputValue()) === 0);
}

/** The times of the Event log rows that lie wholly inside its scrolled view. */
function visibleLogTimes(): Promise<number[]> {
  return page.evaluate(() => {
    const box = document.querySelector(".table-scroll.log")!;
    const view = box.getBoundingClientRect();
    const head = box.querySelector("thead")!.getBoundingClientRect().height;
    return [...box.querySelectorAll("tbody tr:not(.spacer)")]
      .filter((tr) => {
        const r = tr.getBoundingClientRect();
        return r.top >= view.top + head - 1 && r.bottom <= view.bottom + 1;
      })
      .map((tr) => Number(tr.querySelector("td")!.textContent));
  });
}

beforeAll(async () => {
  s = await openEditor();
  page = s.page;
});

afterAll(async () => {
  await s?.close();
});

describe("editor views", () => {
  it("the Event log scrolls to the current time (the events just before and after it are in view)", async () => {
    await loadPreset("Billiards break");
    // the break has dozens of events in its first half second: at t = 1.6 they are all past
    await scrubTo(page, 1.6);
    await poll(async () => {
      const times = await visibleLogTimes();
      return times.some((x) => x <= 1.6) && times.some((x) => x > 1.6);
    }).toBe(true);
    await scrubTo(page, 0.16);
    await poll(async () => {
      const times = await visibleLogTimes();
      return times.some((x) => x <= 0.16) && times.some((x) => x > 0.16);
    }).toBe(true);
    await screenshot(page, "11-event-log-follows-time");
  });
});
