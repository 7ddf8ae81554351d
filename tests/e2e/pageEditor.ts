/**
 * The part of the page's `window.chapgame` (the Editor) and `window.chapgameStats` that the
 * in-browser measurements and profiles use, loading a scene through it, and the scenes they load.
 */
import { readdirSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { dilutedGas } from "@chapgame/engine";
import type { Page } from "playwright-core";
import { DIST } from "./harness.js";

/**
 * Throws when the built editor bundles React's development build (a build run with NODE_ENV other
 * than production): its timings say nothing about the editor users get.
 */
export function assertProductionBuild(): void {
  const dir = join(DIST, "assets");
  for (const f of readdirSync(dir)) {
    if (!/^index-.*\.js$/.test(f)) continue;
    if (readFileSync(join(dir, f), "utf8").includes('unique "key" prop'))
      throw new Error(`${f} bundles React's development build: rebuild with NODE_ENV=production`);
  }
}

export interface PageEditor {
  ui: {
    getState(): { t: number };
    setState(patch: object | ((s: { calc: object }) => object)): void;
  };
  client: {
    getSnapshot(): {
      computing: unknown;
      revision: number;
      horizon: number;
      eventCount: number;
      historyBytes: number;
    };
  };
  loadScene(scene: unknown, options: object): Promise<string | null>;
}

export type PageWindow = {
  chapgame: PageEditor;
  chapgameStats: {
    draws: number;
    drawMs: number;
    frames: number;
    frameLatencyMs: number;
    maxFrameLatencyMs: number;
    heldBodies: number;
    drawnBodies: number;
  };
  chapgameResetStats: () => void;
};

/** Loads a scene and sets the Calculation settings, then waits until the worker is idle (ms taken). */
export async function loadScene(
  page: Page,
  scene: unknown,
  calc: Record<string, unknown>,
  timeoutMs: number,
): Promise<number> {
  await page.evaluate(
    async ({ scene, calc }) => {
      const w = window as unknown as PageWindow;
      w.chapgame.ui.setState((st) => ({ calc: { ...st.calc, ...calc }, playing: false }));
      await w.chapgame.loadScene(scene, { undoable: false });
    },
    { scene, calc },
  );
  const start = Date.now();
  await page.waitForFunction(
    () => {
      const info = (window as unknown as PageWindow).chapgame.client.getSnapshot();
      return info.computing === null && info.revision > 0;
    },
    undefined,
    { timeout: timeoutMs, polling: 200 },
  );
  return Date.now() - start;
}

/**
 * Loads `n` moving discs (a dilute gas: packing 0.1, seed 7), computed 20 s ahead and extended
 * while playing (ms taken, as loadScene).
 */
export function loadPlayingGas(page: Page, n: number, timeoutMs: number): Promise<number> {
  return loadScene(
    page,
    dilutedGas({ n, packing: 0.1, seed: 7 }),
    { useTime: true, seconds: 20, useEvents: false, autoExtend: true },
    timeoutMs,
  );
}

/** Loads 1,000 discs (a dilute gas: packing 0.3, seed 3) with 10^6 events computed (ms taken). */
export function loadScrubbedHistory(page: Page, timeoutMs: number): Promise<number> {
  return loadScene(
    page,
    dilutedGas({ n: 1000, packing: 0.3, seed: 3 }),
    { useTime: false, useEvents: true, events: 1_000_000, autoExtend: false },
    timeoutMs,
  );
}
