/**
 * CPU profiles of the built editor in Debian's Chromium while it plays 2,000 and 20,000 moving discs and while
 * it scrubs 10^6 recorded events (not a test: it reports where the time goes, it asserts nothing).
 * Both the page's main thread and the engine's Web Worker are profiled (cpuProfiles.ts), and the
 * page is traced (timelineTrace.ts). Writes test-artifacts/profile-*.cpuprofile (open in
 * Chromium's DevTools, Performance panel), test-artifacts/trace-*.json and
 * test-artifacts/editor-profile.json (self time per function, top 25, per thread, and the trace's
 * time per kind of event), and prints the summary.
 * Run: npx vitest run --config tests/e2e/profile.config.ts
 */
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, it } from "vitest";
import { profileCpu } from "./cpuProfiles.js";
import { editorForFile } from "./editorForFile.js";
import { ARTIFACTS } from "./harness.js";
import { assertProductionBuild, loadPlayingGas, loadScrubbedHistory, type PageWindow } from "./pageEditor.js";
import { traceTimeline } from "./timelineTrace.js";

const editor = editorForFile({ width: 1400, height: 900, afterOpen: assertProductionBuild });
const results: Record<string, unknown> = {};

afterAll(() => {
  writeFileSync(join(ARTIFACTS, "editor-profile.json"), `${JSON.stringify(results, null, 2)}\n`);
  console.log(JSON.stringify(results, null, 2));
});

/** Profiles, then traces, `run` (two runs of it), keeping both summaries under `name`. */
async function profileAndTrace(name: string, run: () => Promise<{ frames: number }>) {
  results[name] = await profileCpu(editor.page, name, run);
  results[`trace-${name}`] = await traceTimeline(editor.page, name, run);
}

/** Plays (or scrubs) for `ms` and returns the page's animation-frame rate. */
function sample(ms: number, mode: "play" | "scrub") {
  return editor.page.evaluate(
    async ({ ms, mode }) => {
      const ed = (window as unknown as PageWindow).chapgame;
      const horizon = ed.client.getSnapshot().horizon;
      let frames = 0;
      let seed = 12345;
      const start = performance.now();
      if (mode === "play") ed.ui.setState({ t: 0, speed: 1, playing: true });
      await new Promise<void>((resolve) => {
        const tick = () => {
          frames++;
          if (mode === "scrub") {
            seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
            ed.ui.setState({ t: (seed / 4294967296) * horizon });
          }
          if (performance.now() - start < ms) requestAnimationFrame(tick);
          else resolve();
        };
        requestAnimationFrame(tick);
      });
      ed.ui.setState({ playing: false });
      return { frames, pageFps: frames / ((performance.now() - start) / 1000) };
    },
    { ms, mode },
  );
}

it("profiles playing 2,000 moving discs", async () => {
  await loadPlayingGas(editor.page, 2000, 300_000);
  await profileAndTrace("play2000", () => sample(5000, "play"));
});

it("profiles playing 20,000 moving discs", async () => {
  await loadPlayingGas(editor.page, 20_000, 600_000);
  await profileAndTrace("play20000", () => sample(5000, "play"));
});

it("profiles scrubbing 10^6 recorded events", async () => {
  await loadScrubbedHistory(editor.page, 600_000);
  await profileAndTrace("scrub1e6", () => sample(5000, "scrub"));
});
