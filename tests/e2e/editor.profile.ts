/**
 * CPU profiles of the built editor in Debian's Chromium while it plays 2,000 and 20,000 moving discs and while
 * it scrubs 10^6 recorded events (not a test: it reports where the time goes, it asserts nothing).
 * Both the page's main thread and the engine's Web Worker are profiled (the worker through a CDP
 * session attached with Target.setAutoAttach). Writes test-artifacts/profile-*.cpuprofile (open in
 * Chromium's DevTools, Performance panel) and test-artifacts/editor-profile.json (self time per
 * function, top 25, per thread), and prints the summary.
 * Run: npx vitest run --config tests/e2e/profile.config.ts
 */
import { writeFileSync } from "node:fs";
import { loadavg } from "node:os";
import { join } from "node:path";
import { dilutedGas } from "@chapgame/engine";
import type { CDPSession, Page } from "playwright-core";
import { afterAll, beforeAll, it } from "vitest";
import { ARTIFACTS, openEditor, type Session } from "./harness.js";
import { assertProductionBuild, loadScene, type PageWindow } from "./pageEditor.js";

interface ProfileNode {
  id: number;
  callFrame: { functionName: string; url: string; lineNumber: number };
  children?: number[];
}
interface CpuProfile {
  nodes: ProfileNode[];
  samples: number[];
  timeDeltas: number[];
  startTime: number;
  endTime: number;
}

let s: Session;
let page: Page;
const results: Record<string, unknown> = {};

beforeAll(async () => {
  s = await openEditor({ width: 1400, height: 900 });
  page = s.page;
  assertProductionBuild();
});

afterAll(async () => {
  writeFileSync(join(ARTIFACTS, "editor-profile.json"), `${JSON.stringify(results, null, 2)}\n`);
  console.log(JSON.stringify(results, null, 2));
  await s?.close();
});

/** Self time (ms) per function name + file, largest first; "(idle)" and "(program)" included. */
function selfTimes(p: CpuProfile, top = 25) {
  const byId = new Map(p.nodes.map((n) => [n.id, n]));
  const self = new Map<string, number>();
  let total = 0;
  for (let i = 0; i < p.samples.length; i++) {
    const n = byId.get(p.samples[i]!)!;
    const dt = (p.timeDeltas[i + 1] ?? 0) / 1000;
    total += dt;
    const file = n.callFrame.url.split("/").pop() ?? "";
    const key = `${n.callFrame.functionName || "(anonymous)"} ${file}:${n.callFrame.lineNumber + 1}`;
    self.set(key, (self.get(key) ?? 0) + dt);
  }
  const rows = [...self.entries()].sort((a, b) => b[1] - a[1]).slice(0, top);
  return {
    totalMs: Math.round(total),
    top: rows.map(
      ([k, ms]) => `${ms.toFixed(0).padStart(6)} ms ${((100 * ms) / total).toFixed(1).padStart(5)}%  ${k}`,
    ),
  };
}

/** Inclusive time (ms) per function name + file (each counted once per sample), largest first. */
function inclusive(p: CpuProfile, top = 30) {
  const parent = new Map<number, number>();
  for (const n of p.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
  const byId = new Map(p.nodes.map((n) => [n.id, n]));
  const out = new Map<string, number>();
  for (let i = 0; i < p.samples.length; i++) {
    const dt = (p.timeDeltas[i + 1] ?? 0) / 1000;
    const seen = new Set<string>();
    for (let id: number | undefined = p.samples[i]; id !== undefined; id = parent.get(id)) {
      const f = byId.get(id)!.callFrame;
      if (!f.url || f.functionName === "") continue;
      const key = `${f.functionName} ${f.url.split("/").pop()}:${f.lineNumber + 1}`;
      if (seen.has(key)) continue;
      seen.add(key);
      out.set(key, (out.get(key) ?? 0) + dt);
    }
  }
  return [...out.entries()]
    .sort((a, b) => b[1] - a[1])
    .slice(0, top)
    .map(([k, ms]) => `${ms.toFixed(0).padStart(6)} ms  ${k}`);
}

/** A CDP session on the page and one relayed to its (first) dedicated worker. */
async function sessions(): Promise<{
  main: CDPSession;
  worker: (method: string, params?: object) => Promise<unknown>;
}> {
  const main = await page.context().newCDPSession(page);
  let workerSession = "";
  let nextId = 1;
  const waiting = new Map<number, (v: unknown) => void>();
  main.on("Target.receivedMessageFromTarget", (e: { sessionId: string; message: string }) => {
    const m = JSON.parse(e.message) as { id?: number; result?: unknown; error?: unknown };
    if (m.id !== undefined && waiting.has(m.id)) {
      waiting.get(m.id)!(m.error ? Promise.reject(new Error(JSON.stringify(m.error))) : m.result);
      waiting.delete(m.id);
    }
  });
  const attached = new Promise<void>((resolve) => {
    main.on("Target.attachedToTarget", (e: { sessionId: string; targetInfo: { type: string } }) => {
      if (e.targetInfo.type === "worker" && !workerSession) {
        workerSession = e.sessionId;
        resolve();
      }
    });
  });
  await main.send("Target.setAutoAttach", {
    autoAttach: true,
    waitForDebuggerOnStart: false,
    flatten: false,
  });
  await attached;
  const worker = (method: string, params: object = {}) =>
    new Promise<unknown>((resolve) => {
      const id = nextId++;
      waiting.set(id, resolve);
      void main.send("Target.sendMessageToTarget", {
        sessionId: workerSession,
        message: JSON.stringify({ id, method, params }),
      });
    });
  return { main, worker };
}

async function profile(name: string, run: () => Promise<unknown>) {
  const { main, worker } = await sessions();
  for (const send of [(m: string, p?: object) => main.send(m as "Profiler.enable", p), worker]) {
    await send("Profiler.enable");
    await send("Profiler.setSamplingInterval", { interval: 200 });
    await send("Profiler.start");
  }
  const load0 = loadavg()[0];
  const measured = await run();
  const mainProfile = (await main.send("Profiler.stop")).profile as unknown as CpuProfile;
  const workerProfile = ((await worker("Profiler.stop")) as { profile: CpuProfile }).profile;
  writeFileSync(join(ARTIFACTS, `profile-${name}-main.cpuprofile`), JSON.stringify(mainProfile));
  writeFileSync(join(ARTIFACTS, `profile-${name}-worker.cpuprofile`), JSON.stringify(workerProfile));
  results[name] = {
    loadAverage1min: [load0, loadavg()[0]],
    measured,
    main: { ...selfTimes(mainProfile), inclusive: inclusive(mainProfile) },
    worker: { ...selfTimes(workerProfile), inclusive: inclusive(workerProfile) },
  };
  await main.detach();
}

interface TraceEvent {
  name: string;
  ph: string;
  pid: number;
  tid: number;
  ts: number;
  dur?: number;
  /** thread (CPU) duration */
  tdur?: number;
  args?: { name?: string };
}

/**
 * A Chromium trace (devtools.timeline categories) of `run`: per thread, the time in each kind of
 * trace event (events nest, so a RunTask contains its FunctionCall, Paint... : read them as a tree).
 */
async function trace(name: string, run: () => Promise<unknown>) {
  const cdp = await page.context().newCDPSession(page);
  const events: TraceEvent[] = [];
  cdp.on("Tracing.dataCollected", (e) => {
    events.push(...(e.value as unknown as TraceEvent[]));
  });
  const done = new Promise<void>((resolve) => cdp.once("Tracing.tracingComplete", () => resolve()));
  await cdp.send("Tracing.start", {
    transferMode: "ReportEvents",
    traceConfig: {
      includedCategories: [
        "devtools.timeline",
        "disabled-by-default-devtools.timeline",
        "disabled-by-default-devtools.timeline.frame",
        "blink",
        "cc",
        "gpu",
        "viz",
        "toplevel",
        "v8",
        "blink.user_timing",
      ],
    },
  });
  const load0 = loadavg()[0];
  const measured = await run();
  await cdp.send("Tracing.end");
  await done;
  writeFileSync(join(ARTIFACTS, `trace-${name}.json`), JSON.stringify({ traceEvents: events }));
  const threadNames = new Map<string, string>();
  for (const e of events)
    if (e.ph === "M" && e.name === "thread_name") threadNames.set(`${e.pid}:${e.tid}`, e.args?.name ?? "");
  const perThread = new Map<string, Map<string, { ms: number; n: number }>>();
  for (const e of events) {
    if (e.ph !== "X" || e.dur === undefined) continue;
    const th = threadNames.get(`${e.pid}:${e.tid}`) ?? `${e.pid}:${e.tid}`;
    let m = perThread.get(th);
    if (!m) {
      m = new Map();
      perThread.set(th, m);
    }
    const r = m.get(e.name) ?? { ms: 0, n: 0 };
    r.ms += e.dur / 1000;
    r.n++;
    m.set(e.name, r);
  }
  const threads: Record<string, string[]> = {};
  for (const [th, m] of perThread) {
    const rows = [...m.entries()].sort((a, b) => b[1].ms - a[1].ms).slice(0, 30);
    if ((rows[0]?.[1].ms ?? 0) < 50) continue;
    threads[th] = rows.map(([k, r]) => `${r.ms.toFixed(0).padStart(6)} ms ${String(r.n).padStart(5)}x  ${k}`);
  }
  results[`trace-${name}`] = {
    loadAverage1min: [load0, loadavg()[0]],
    measured,
    cpuMsPerFrame: cpuPerFrame(events, threadNames, (measured as { frames: number }).frames),
    threads,
  };
  await cdp.detach();
}

/**
 * CPU time (ms, from the trace's thread durations) per animation frame, per thread name: the sum of
 * each thread's outermost trace events. Less sensitive to other processes' load than frame rates.
 */
function cpuPerFrame(events: TraceEvent[], threadNames: Map<string, string>, frames: number) {
  const byThread = new Map<string, TraceEvent[]>();
  for (const e of events) {
    if (e.ph !== "X" || e.tdur === undefined || e.dur === undefined) continue;
    const k = `${e.pid}:${e.tid}`;
    const list = byThread.get(k) ?? [];
    list.push(e);
    byThread.set(k, list);
  }
  const out: Record<string, number> = {};
  for (const [k, list] of byThread) {
    list.sort((a, b) => a.ts - b.ts || (b.dur ?? 0) - (a.dur ?? 0));
    let end = -1;
    let cpu = 0;
    for (const e of list)
      if (e.ts >= end) {
        cpu += e.tdur!;
        end = e.ts + e.dur!;
      }
    const name = (threadNames.get(k) ?? k).replace(/\d+$/, "");
    out[name] = (out[name] ?? 0) + cpu / 1000 / Math.max(frames, 1);
  }
  for (const [k, v] of Object.entries(out))
    if (v < 0.1) delete out[k];
    else out[k] = Math.round(v * 100) / 100;
  return out;
}

/** Plays (or scrubs) for `ms` and returns the page's animation-frame rate. */
function sample(ms: number, mode: "play" | "scrub") {
  return page.evaluate(
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
  await loadScene(
    page,
    dilutedGas({ n: 2000, packing: 0.1, seed: 7 }),
    { useTime: true, seconds: 20, useEvents: false, autoExtend: true },
    300_000,
  );
  await profile("play2000", () => sample(5000, "play"));
  await trace("play2000", () => sample(5000, "play"));
});

it("profiles playing 20,000 moving discs", async () => {
  await loadScene(
    page,
    dilutedGas({ n: 20_000, packing: 0.1, seed: 7 }),
    { useTime: true, seconds: 20, useEvents: false, autoExtend: true },
    600_000,
  );
  await profile("play20000", () => sample(5000, "play"));
  await trace("play20000", () => sample(5000, "play"));
});

it("profiles scrubbing 10^6 recorded events", async () => {
  await loadScene(
    page,
    dilutedGas({ n: 1000, packing: 0.3, seed: 3 }),
    { useTime: false, useEvents: true, events: 1_000_000, autoExtend: false },
    600_000,
  );
  await profile("scrub1e6", () => sample(5000, "scrub"));
  await trace("scrub1e6", () => sample(5000, "scrub"));
});
