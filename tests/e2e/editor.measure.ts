/**
 * In-browser measurements of the built editor in Debian's Chromium (not a test: it reports numbers,
 * it asserts nothing about time). Writes test-artifacts/editor-perf.json and prints a summary.
 *  1. Playing 2,000 moving discs (a dilute gas): animation frames per second of the page, canvas
 *     redraws per second, drawing time per frame, frame round trip to the worker.
 *     The same across the horizon: playing from 2.5 s before it while the worker computes ahead.
 *     The same with 20,000 moving discs (from t = 0, so the first frames' motion laws span the
 *     scene's 20,000 add actions at t = 0).
 *  2. Scrubbing a timeline with 10^6 recorded events: a new random time every animation frame.
 * Each sample runs MEASURE_RUNS times (default 3) and reports every run (with the load average
 * before and after it) and the medians of frames per second and of the 95th percentile frame gap.
 * Run: npx vitest run --config tests/e2e/measure.config.ts (builds the editor when its sources are
 * newer than its dist). CHAPGAME_ENGINE_SRC=<other engine copy>/src/index.ts builds against another
 * engine source (while the engine is being edited); CHAPGAME_E2E_DIST=<dir> measures another build.
 */
import { writeFileSync } from "node:fs";
import { cpus, loadavg } from "node:os";
import { join } from "node:path";
import { afterAll, it } from "vitest";
import { editorForFile } from "./editorForFile.js";
import { ARTIFACTS, screenshot } from "./harness.js";
import { assertProductionBuild, loadPlayingGas, loadScrubbedHistory, type PageWindow } from "./pageEditor.js";

const editor = editorForFile({ width: 1400, height: 900, afterOpen: assertProductionBuild });
const results: Record<string, unknown> = {};

afterAll(() => {
  results.machine = { cpus: cpus().length, loadAverage1min: loadavg()[0] };
  writeFileSync(join(ARTIFACTS, "editor-perf.json"), `${JSON.stringify(results, null, 2)}\n`);
  console.log(JSON.stringify(results, null, 2));
});

/** The page's editor's snapshot of its worker's computation (horizon, events, history size). */
const snapshot = () =>
  editor.page.evaluate(() => (window as unknown as PageWindow).chapgame.client.getSnapshot());

/** play: from t = 0; extend: from 2.5 s before the horizon (auto-extend computes while playing). */
type Mode = "play" | "extend" | "scrub";

/** A frame gap longer than this (1.5 intervals of headless Chromium's 60 Hz frame clock) dropped a frame. */
const DROPPED_GAP_MS = 25;

/** How many times each sample is taken (the report gives each run and the median). */
const RUNS = Number(process.env.MEASURE_RUNS ?? 3);

/**
 * Counts animation frames and editor draws during `ms` (playing, or scrubbing to a new random time
 * every animation frame). Frame gaps are the times between animation frames (p50/p95/p99); long
 * tasks (> 50 ms) and long animation frames (with the scripts that took the most time in them) come
 * from Chromium's PerformanceObservers.
 */
async function sampleOnce(ms: number, mode: Mode) {
  const load = loadavg()[0];
  const r = await editor.page.evaluate(
    async ({ ms, mode, DROPPED_GAP_MS }) => {
      const w = window as unknown as PageWindow;
      const ed = w.chapgame;
      const horizon = ed.client.getSnapshot().horizon;
      const longTasks: number[] = [];
      const scripts = new Map<string, number>();
      const observers: PerformanceObserver[] = [];
      const observe = (type: string, fn: (e: PerformanceEntry) => void) => {
        if (!PerformanceObserver.supportedEntryTypes.includes(type)) return;
        const o = new PerformanceObserver((list) => list.getEntries().forEach(fn));
        o.observe({ type });
        observers.push(o);
      };
      observe("longtask", (e) => longTasks.push(e.duration));
      observe("long-animation-frame", (e) => {
        for (const sc of (
          e as unknown as { scripts: { invoker: string; sourceFunctionName: string; duration: number }[] }
        ).scripts) {
          const k = `${sc.invoker} ${sc.sourceFunctionName}`;
          scripts.set(k, (scripts.get(k) ?? 0) + sc.duration);
        }
      });
      w.chapgameResetStats();
      const gaps: number[] = [];
      let last = performance.now();
      const start = last;
      let seed = 12345;
      const rand = () => {
        seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
        return seed / 4294967296;
      };
      if (mode === "play") ed.ui.setState({ t: 0, speed: 1, playing: true });
      if (mode === "extend") ed.ui.setState({ t: Math.max(0, horizon - 2.5), speed: 1, playing: true });
      await new Promise<void>((resolve) => {
        // Gaps between the frames' timestamps (the frame's start, aligned to the display's refresh):
        // a dropped frame shows as a gap of two refresh intervals, not as callback jitter.
        const tick = (now: number) => {
          gaps.push(now - last);
          last = now;
          if (mode === "scrub") ed.ui.setState({ t: rand() * horizon });
          if (now - start < ms) requestAnimationFrame(tick);
          else resolve();
        };
        requestAnimationFrame(tick);
      });
      ed.ui.setState({ playing: false });
      await new Promise((r) => setTimeout(r, 100)); // let the observers report
      for (const o of observers) o.disconnect();
      const secs = (performance.now() - start) / 1000;
      const st = w.chapgameStats;
      gaps.shift(); // from the start to the first frame
      gaps.sort((a, b) => a - b);
      const pct = (q: number) => gaps[Math.min(gaps.length - 1, Math.floor(q * gaps.length))] ?? null;
      return {
        seconds: secs,
        // from the gaps between animation frames (the same measure as the bare-canvas baseline)
        pageFps: (1000 * gaps.length) / gaps.reduce((a, b) => a + b, 0),
        frameGapMs: { p50: pct(0.5), p95: pct(0.95), p99: pct(0.99), max: gaps[gaps.length - 1] ?? null },
        /** Share of frame gaps longer than 1.5 refresh intervals (a frame or more dropped). */
        droppedShare: gaps.filter((g) => g > DROPPED_GAP_MS).length / Math.max(1, gaps.length),
        longTasks: {
          count: longTasks.length,
          totalMs: longTasks.reduce((a, b) => a + b, 0),
          maxMs: Math.max(0, ...longTasks),
        },
        longFrameScripts: [...scripts.entries()]
          .sort((a, b) => b[1] - a[1])
          .slice(0, 6)
          .map(([k, v]) => `${v.toFixed(0)} ms ${k}`),
        canvasDrawsPerSecond: st.draws / secs,
        meanDrawMs: st.draws ? st.drawMs / st.draws : null,
        framesFromWorkerPerSecond: st.frames / secs,
        meanFrameRoundTripMs: st.frames ? st.frameLatencyMs / st.frames : null,
        maxFrameRoundTripMs: st.maxFrameLatencyMs,
        /** Share of drawn bodies waiting for the worker's answer at an event (not at the exact time). */
        heldBodiesShare: st.drawnBodies ? st.heldBodies / st.drawnBodies : null,
        reachedT: ed.ui.getState().t,
        horizon,
        horizonAfter: ed.client.getSnapshot().horizon,
      };
    },
    { ms, mode, DROPPED_GAP_MS },
  );
  return { loadAverage1min: [load, loadavg()[0]], ...r };
}

/** RUNS samples; the summary gives the medians of fps and p95 frame gap. */
async function sample(ms: number, mode: Mode) {
  const runs = [];
  for (let i = 0; i < RUNS; i++) runs.push(await sampleOnce(ms, mode));
  const median = (xs: number[]) => xs.sort((a, b) => a - b)[Math.floor(xs.length / 2)]!;
  return {
    medianPageFps: median(runs.map((r) => r.pageFps)),
    medianP95FrameGapMs: median(runs.map((r) => r.frameGapMs.p95 ?? Number.NaN)),
    medianDroppedShare: median(runs.map((r) => r.droppedShare)),
    runs,
  };
}

/** Plays `n` moving discs from t = 0 (loaded and computed 20 s ahead first) and samples it. */
async function playingGas(n: number, timeoutMs: number) {
  const computeMs = await loadPlayingGas(editor.page, n, timeoutMs);
  const info = await snapshot();
  const played = {
    bodies: n,
    computeAheadMs: computeMs,
    eventsIn20s: info.eventCount,
    ...(await sample(6000, "play")),
  };
  await screenshot(editor.page, `perf-${n}-discs`);
  return played;
}

it("plays 2,000 moving discs", async () => {
  results.play2000 = await playingGas(2000, 300_000);
});

it("plays 2,000 moving discs across the horizon (computing ahead while playing)", async () => {
  results.extend2000 = await sample(6000, "extend");
});

it("plays 20,000 moving discs", async () => {
  results.play20000 = await playingGas(20_000, 600_000);
});

it("scrubs a timeline with 10^6 recorded events", async () => {
  const computeMs = await loadScrubbedHistory(editor.page, 600_000);
  const info = await snapshot();
  results.scrub1e6 = {
    bodies: 1000,
    events: info.eventCount,
    historyBytes: info.historyBytes,
    computeMs,
    ...(await sample(6000, "scrub")),
  };
  await screenshot(editor.page, "perf-scrub-1e6");
});

/** A bare page drawing n circles per frame in one path (the machine's ceiling under its current load). */
async function bareCanvas(n: number) {
  const other = await editor.session.context.newPage();
  await other.setContent('<canvas id="c" width="1000" height="800"></canvas>');
  const load = loadavg()[0];
  const bare = await other.evaluate(
    async ({ droppedGapMs, n }) => {
      const ctx = (document.getElementById("c") as HTMLCanvasElement).getContext("2d")!;
      let frames = 0;
      const start = performance.now();
      let last = start;
      const gaps: number[] = [];
      await new Promise<void>((resolve) => {
        const tick = (now: number) => {
          frames++;
          gaps.push(now - last);
          last = now;
          ctx.fillStyle = "#fff";
          ctx.fillRect(0, 0, 1000, 800);
          ctx.beginPath();
          for (let i = 0; i < n; i++) {
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
      gaps.shift();
      gaps.sort((a, b) => a - b);
      return {
        pageFps: (1000 * gaps.length) / gaps.reduce((a, b) => a + b, 0),
        p95FrameGapMs: gaps[Math.floor(0.95 * gaps.length)],
        droppedShare: gaps.filter((g) => g > droppedGapMs).length / gaps.length,
      };
    },
    { droppedGapMs: DROPPED_GAP_MS, n },
  );
  await other.close();
  return { loadAverage1min: [load, loadavg()[0]], ...bare };
}

it("baseline: a bare page drawing 2,000 circles per frame", async () => {
  results.bareCanvas2000 = await bareCanvas(2000);
});

it("baseline: a bare page drawing 20,000 circles per frame", async () => {
  results.bareCanvas20000 = await bareCanvas(20_000);
});
