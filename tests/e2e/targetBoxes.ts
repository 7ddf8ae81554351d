/**
 * What the editor's target-size end-to-end tests share (WCAG 2.2, 2.5.8: target size, minimum): the
 * 24 px minimum, every window size the editor's end-to-end tests use, the targets a selector finds
 * (each named, with the border box a pointer hits) and the check that each is at least 24 x 24 px
 * with no two overlapping. Contract: `targetsOf` leaves out what is not drawn (no box, or hidden).
 */
import type { Page } from "playwright-core";
import { expect } from "vitest";
import { TWO_COLUMN_WINDOWS, type WindowSize } from "./windowSize.js";

/** The WCAG 2.2 minimum target size (2.5.8), CSS px each way. */
export const MIN_TARGET_PX = 24;

/** Every window size the editor's end-to-end tests use (two columns, short, stacked, phone). */
export const TARGET_SIZES: WindowSize[] = [
  ...TWO_COLUMN_WINDOWS,
  [1920, 900],
  [2560, 1440],
  [1600, 900],
  [1280, 800],
  [1024, 700],
  [1000, 700],
  [900, 700],
  [800, 600],
  [700, 800],
  [400, 800],
  [390, 844],
  [950, 450],
  [1050, 480],
  [900, 500],
  [1280, 480],
  [844, 390],
  [740, 360],
  [700, 420],
  [667, 375],
];

/** A target's accessible name and border box (what a pointer hits). */
export interface Target {
  name: string;
  x: number;
  y: number;
  width: number;
  height: number;
}

/** Each drawn element `selector` finds on `page`, as a target (one not drawn, as More in a wide
 *  window or the digits' field of a preset without digits, is left out). */
export function targetsOf(page: Page, selector: string): Promise<Target[]> {
  return page.evaluate(
    (selector) =>
      Array.from(document.querySelectorAll(selector))
        .map((el) => {
          const r = el.getBoundingClientRect();
          const label = (el as HTMLInputElement).labels?.[0]?.textContent;
          const name = el.getAttribute("aria-label") ?? label ?? el.textContent!.trim();
          const drawn = getComputedStyle(el).visibility !== "hidden";
          return { name, x: r.x, y: r.y, width: drawn ? r.width : 0, height: r.height };
        })
        .filter((t) => t.width > 0 && t.height > 0),
    selector,
  );
}

/** Expects each target at least 24 x 24 px, and no two of them overlapping. */
export function expectTargets(at: string, all: Target[]): void {
  for (const t of all) {
    expect(t.width, `${at}: ${t.name} wide`).toBeGreaterThanOrEqual(MIN_TARGET_PX);
    expect(t.height, `${at}: ${t.name} high`).toBeGreaterThanOrEqual(MIN_TARGET_PX);
  }
  for (const [i, a] of all.entries())
    for (const b of all.slice(i + 1)) {
      const overlapX = Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x);
      const overlapY = Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y);
      expect(overlapX > 0.5 && overlapY > 0.5, `${at}: ${a.name} overlaps ${b.name}`).toBe(false);
    }
}

/** The targets' names, in document order. */
export const names = (all: Target[]) => all.map((t) => t.name);
