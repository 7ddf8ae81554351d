/**
 * CPU profiles of a page and of its (first) dedicated Web Worker, through the Chrome DevTools
 * Protocol, for the in-browser profiles (editor.profile.ts). Contract: `profileCpu(page, name, run)`
 * samples both threads while `run` runs, writes test-artifacts/profile-<name>-main.cpuprofile and
 * -worker.cpuprofile (open them in Chromium's DevTools, Performance panel), and returns what `run`
 * returned with each thread's summary: self time per function (top 25, "(idle)" and "(program)"
 * included) and inclusive time per function (top 30), and the load average before and after.
 */
import { writeFileSync } from "node:fs";
import { loadavg } from "node:os";
import { join } from "node:path";
import type { CDPSession, Page } from "playwright-core";
import { ARTIFACTS } from "./harness.js";

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
async function sessions(page: Page): Promise<{
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

/** Profiles the page's main thread and its worker while `run` runs; see the header. */
export async function profileCpu(page: Page, name: string, run: () => Promise<unknown>) {
  const { main, worker } = await sessions(page);
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
  await main.detach();
  return {
    loadAverage1min: [load0, loadavg()[0]],
    measured,
    main: { ...selfTimes(mainProfile), inclusive: inclusive(mainProfile) },
    worker: { ...selfTimes(workerProfile), inclusive: inclusive(workerProfile) },
  };
}
