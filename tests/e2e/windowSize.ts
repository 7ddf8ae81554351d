/**
 * Resizing the editor's window in an end-to-end test and putting it back: the tests of a file share
 * one window (editorForFile), so a test that resizes it leaves it as openEditor opened it
 * (DEFAULT_WINDOW), even when it fails. Contract: `withWindowSize` runs its function in one size,
 * `forEachWindowSize` runs its function once per size (in the order given, the window resized
 * before each call); both put the window back to DEFAULT_WINDOW when they end, however they end.
 */
import type { Page } from "playwright-core";
import { DEFAULT_WINDOW } from "./harness.js";

/** A window size: width and height in CSS px. */
export type WindowSize = readonly [width: number, height: number];

/** The two-column layout's widths where the header, toolbar and time bar change (900 px high;
 *  1920 × 1080 as a common desktop): what the stage-lines and target-size tests measure. */
export const TWO_COLUMN_WINDOWS: readonly WindowSize[] = [
  [901, 900],
  [950, 900],
  [1000, 900],
  [1001, 900],
  [1050, 900],
  [1100, 900],
  [1200, 900],
  [1279, 900],
  [1280, 900],
  [1400, 900],
  [1920, 1080],
];

/** Runs `fn` in a `width` × `height` window, then puts the window back to DEFAULT_WINDOW. */
export async function withWindowSize<T>(
  page: Page,
  width: number,
  height: number,
  fn: () => Promise<T>,
): Promise<T> {
  try {
    await page.setViewportSize({ width, height });
    return await fn();
  } finally {
    await page.setViewportSize(DEFAULT_WINDOW);
  }
}

/** Runs `fn(width, height)` in a window of each size in turn, then puts it back to DEFAULT_WINDOW. */
export async function forEachWindowSize(
  page: Page,
  sizes: readonly WindowSize[],
  fn: (width: number, height: number) => Promise<void>,
): Promise<void> {
  try {
    for (const [width, height] of sizes) {
      await page.setViewportSize({ width, height });
      await fn(width, height);
    }
  } finally {
    await page.setViewportSize(DEFAULT_WINDOW);
  }
}
