/**
 * In-browser measurements of the built editor in Debian's Chromium (not a test: it reports numbers,
 * it asserts nothing about time). Writes test-artifacts/editor-perf.json and prints a summary.
 *  1. Playing 2,000 moving discs (a dilute gas): animation frames per second of the page, canvas
 *     redraws per second, drawing time per frame, frame round trip to the worker.
 *  2. Scrubbing a timeline with 10^6 recorded events: a new random time every animation frame.
 * Run: npm run build && (cd packages/editor && npx vite build) && npx vitest run --config tests/e2e/measure.config.ts
 */
import { writeFileSync } from "node:fs";
import { cpus, loadavg } from "node:os";
import { join } from "node:path";
import { dilutedGas } from "@chapgame/engine";
import type { Page } from "playwright-core";
import { afterAll, beforeAll, it } from "vitest";
import { ARTIFACTS, openEditor, type Session, screenshot } from "./harness.js";

/** The part of the page's `window.chapgame` (the Editor) these measurements use. */
interface PageEditor {
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
type PageWindow = {
  chapgame: PageEditor;
  chapgameStats: {
    draws: number;
    drawMs: number;
    frames: number;
    frameLatencyMs: number;
    maxFrameLatencyMs: number;
  };
  chapgameResetStats: () => void;
};

let s: Session;
let page: Page;
const results: Record<string, unknown> = {};

beforeAll(async () => {
  s = await openEditor({ width: 1400, height: 900 });
  page = s.page;
});

afterAll(async () => {
  results.machine = { cpus: cpus().length, loadAverage1min: loadavg()[0] };
  writeFileSync(join(ARTIFACTS, "editor-perf.json"), `${JSON.stringify(results, null, 2)}\n`);
  console.log(JSON.stringify(results, null, 2));
  await s?.close();
});

/** Loads a scene and sets the Calculation settings, then waits until the worker is idle. */
async function load(scene: unknown, calc: Record<string, unknown>, timeoutMs: number) {
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

/** Counts animation frames and editor draws during `ms` while `perFrame` runs on every frame. */
async function sample(ms: number, mode: "play" | "scrub") {
  return page.evaluate(
    async ({ ms, mode }) => {
      const w = window as unknown as PageWindow;
      const ed = w.chapgame;
      const horizon = ed.client.getSnapshot().horizon;
      w.chapgameResetStats();
      let frames = 0;
      let worst = 0;
      let last = performance.now();
      const start = last;
      let seed = 12345;
      const rand = () => {
        seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
        return seed / 4294967296;
      };
      if (mode === "play") ed.ui.setState({ t: 0, speed: 1, playing: true });
      await new Promise<void>((resolve) => {
        const tick = () => {
          const now = performance.now();
          frames++;
          worst = Math.max(worst, now - last);
          last = now;
          if (mode === "scrub") ed.ui.setState({ t: rand() * horizon });
          if (now - start < ms) requestAnimationFrame(tick);
          else resolve();
        };
        requestAnimationFrame(tick);
      });
      ed.ui.setState({ playing: false });
      const secs = (performance.now() - start) / 1000;
      const st = w.chapgameStats;
      return {
        seconds: secs,
        pageFps: frames / secs,
        worstFrameGapMs: worst,
        canvasDrawsPerSecond: st.draws / secs,
        meanDrawMs: st.draws ? st.drawMs / st.draws : null,
        framesFromWorkerPerSecond: st.frames / secs,
        meanFrameRoundTripMs: st.frames ? st.frameLatencyMs / st.frames : null,
        maxFrameRoundTripMs: st.maxFrameLatencyMs,
        reachedT: ed.ui.getState().t,
        horizon,
      };
    },
    { ms, mode },
  );
}

it("plays 2,000 moving discs", async () => {
  const scene = dilutedGas({ n: 2000, packing: 0.1, seed: 7 });
  const computeMs = await load(
    scene,
    { useTime: true, seconds: 20, useEvents: false, autoExtend: true },
    300_000,
  );
  const info = await page.evaluate(() => (window as unknown as PageWindow).chapgame.client.getSnapshot());
  results.play2000 = {
    bodies: 2000,
    computeAheadMs: computeMs,
    eventsIn20s: info.eventCount,
    ...(await sample(8000, "play")),
  };
  await screenshot(page, "perf-2000-discs");
});

it("scrubs a timeline with 10^6 recorded events", async () => {
  const scene = dilutedGas({ n: 1000, packing: 0.3, seed: 3 });
  const computeMs = await load(
    scene,
    { useTime: false, useEvents: true, events: 1_000_000, autoExtend: false },
    600_000,
  );
  const info = await page.evaluate(() => (window as unknown as PageWindow).chapgame.client.getSnapshot());
  results.scrub1e6 = {
    bodies: 1000,
    events: info.eventCount,
    historyBytes: info.historyBytes,
    computeMs,
    ...(await sample(8000, "scrub")),
  };
  await screenshot(page, "perf-scrub-1e6");
});

it("baseline: a bare page drawing 2,000 circles per frame (the machine's ceiling under its current load)", async () => {
  const other = await s.context.newPage();
  await other.setContent('<canvas id="c" width="1000" height="800"></canvas>');
  results.bareCanvas2000 = await other.evaluate(async () => {
    const ctx = (document.getElementById("c") as HTMLCanvasElement).getContext("2d")!;
    let frames = 0;
    const start = performance.now();
    await new Promise<void>((resolve) => {
      const tick = () => {
        frames++;
        ctx.fillStyle = "#fff";
        ctx.fillRect(0, 0, 1000, 800);
        ctx.beginPath();
        for (let i = 0; i < 2000; i++) {
          const x = (i * 37 + frames) % 1000;
          const y = (i * 91) % 800;
          ctx.moveTo(x + 3, y);
          ctx.arc(x, y, 3, 0, 2 * Math.PI);
        }
        ctx.stroke();
        if (performance.now() - start < 5000) requestAnimationFrame(tick);
        else resolve();
      };
      requestAnimationFrame(tick);
    });
    return { pageFps: frames / ((performance.now() - start) / 1000) };
  });
  await other.close();
});
