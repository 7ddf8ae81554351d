/**
 * A scene of equal discs at rest in a grid, for the e2e tests that need a Bodies table longer than
 * its view, and the open step that loads it and waits for the table's first row.
 */
import type { Page } from "playwright-core";
import { POLL_TIMEOUT_MS } from "./editorForFile.js";
import { waitFor } from "./harness.js";
import { loadScene } from "./pageEditor.js";

/** `count` discs b1, b2, … of radius 3, 20 apart, `perRow` to a row, at rest; `extra` actions first. */
export function bodyGridScene(count: number, perRow: number, extra: object[] = []): object {
  const actions: object[] = [...extra];
  for (let i = 0; i < count; i++)
    actions.push({
      time: 0,
      type: "addBody",
      id: `b${i + 1}`,
      x: (i % perRow) * 20,
      y: Math.floor(i / perRow) * 20,
      r: 3,
      m: 1,
      mu: 0,
      v: [0, 0],
    });
  return { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions };
}

/** Loads `scene` (one second computed ahead) and waits until the Bodies table shows b1. */
export async function openBodyGrid(page: Page, scene: object): Promise<void> {
  await loadScene(page, scene, { useTime: true, seconds: 1, useEvents: false, autoExtend: false }, 60_000);
  const cell = page.getByRole("table", { name: "Bodies" }).getByLabel("b1 x", { exact: true });
  await waitFor(async () => (await cell.count()) === 1, POLL_TIMEOUT_MS);
}
