/**
 * A Chromium trace (devtools.timeline categories) of a page, through the Chrome DevTools Protocol,
 * for the in-browser profiles (editor.profile.ts). Contract: `traceTimeline(page, name, run)` traces
 * while `run` runs (which must return `{ frames }`, the animation frames it saw), writes
 * test-artifacts/trace-<name>.json, and returns what `run` returned with, per thread, the time in
 * each kind of trace event (top 30; threads under 50 ms left out; events nest, so a RunTask
 * contains its FunctionCall, Paint...: read them as a tree), the CPU time per animation frame of
 * each thread, and the load average before and after.
 */
import { writeFileSync } from "node:fs";
import { loadavg } from "node:os";
import { join } from "node:path";
import type { Page } from "playwright-core";
import { ARTIFACTS } from "./harness.js";

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

/** The trace categories recorded: the DevTools timeline's, with rendering's and V8's. */
const CATEGORIES = [
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
];

/** Traces the page while `run` runs; see the header. */
export async function traceTimeline(page: Page, name: string, run: () => Promise<{ frames: number }>) {
  const cdp = await page.context().newCDPSession(page);
  const events: TraceEvent[] = [];
  cdp.on("Tracing.dataCollected", (e) => {
    events.push(...(e.value as unknown as TraceEvent[]));
  });
  const done = new Promise<void>((resolve) => cdp.once("Tracing.tracingComplete", () => resolve()));
  await cdp.send("Tracing.start", {
    transferMode: "ReportEvents",
    traceConfig: { includedCategories: CATEGORIES },
  });
  const load0 = loadavg()[0];
  const measured = await run();
  await cdp.send("Tracing.end");
  await done;
  await cdp.detach();
  writeFileSync(join(ARTIFACTS, `trace-${name}.json`), JSON.stringify({ traceEvents: events }));
  const threadNames = new Map<string, string>();
  for (const e of events)
    if (e.ph === "M" && e.name === "thread_name") threadNames.set(`${e.pid}:${e.tid}`, e.args?.name ?? "");
  return {
    loadAverage1min: [load0, loadavg()[0]],
    measured,
    cpuMsPerFrame: cpuPerFrame(events, threadNames, measured.frames),
    threads: timePerEventKind(events, threadNames),
  };
}

/** Per thread (threads under 50 ms left out), the time in each kind of event, top 30. */
function timePerEventKind(events: TraceEvent[], threadNames: Map<string, string>) {
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
  return threads;
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
