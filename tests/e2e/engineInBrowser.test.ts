/**
 * End-to-end: the engine README's promise "the same input gives bit-identical results in Node and
 * in every browser", checked against Debian's Chromium. Contract: each scene of engineScenes.ts
 * (a dilute gas, the gas under friction run to rest, elastic balls under gravity among lines, rays,
 * segments and points, Galperin's billiard) is run in Node on the built engine and, independently,
 * in a Chromium page that imports the same dist from a static server (no editor, no Node result
 * sent to the page: only the scene function's source). Every event (time, kind, ids, contact point,
 * normal, impulse), every body's final state and the final time must have identical IEEE-754 bit
 * patterns; a failure names the scene and the first differing event.
 */
import { execFileSync } from "node:child_process";
import { existsSync, readdirSync, statSync } from "node:fs";
import { join } from "node:path";
import * as engine from "@chapgame/engine";
import { type Browser, chromium, type Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { runScene, SCENES, type SceneRun } from "./engineScenes.js";
import { ROOT } from "./harness.js";
import { type StaticServer, serveStatic } from "./server.js";

const ENGINE = join(ROOT, "packages/engine");
const DIST = join(ENGINE, "dist");

/** Newest modification time (ms) of the files under `path`. */
function newest(path: string): number {
  const st = statSync(path);
  if (!st.isDirectory()) return st.mtimeMs;
  return readdirSync(path).reduce((m, name) => Math.max(m, newest(join(path, name))), st.mtimeMs);
}

/** Builds the engine when its dist is missing or older than its sources (as `npm test` does first). */
function ensureEngineBuilt(): void {
  const index = join(DIST, "index.js");
  if (existsSync(index) && newest(join(ENGINE, "src")) < statSync(index).mtimeMs) return;
  execFileSync("npm", ["run", "build", "-w", "@chapgame/engine"], { cwd: ROOT, stdio: "inherit" });
}

/** A "kind a b hex..." line with each hex field decoded, for a readable failure message. */
function decode(line: string | undefined): string {
  if (line === undefined) return "(none)";
  return line
    .split(" ")
    .map((f) => (/^[0-9a-f]{16}$/.test(f) ? `${f}(${Buffer.from(f, "hex").readDoubleBE(0)})` : f))
    .join(" ");
}

/** null when the two runs agree bit for bit, else where they first differ. */
function firstDifference(node: SceneRun, browser: SceneRun): string | null {
  const n = node.scene;
  for (let i = 0; i < Math.max(node.events.length, browser.events.length); i++)
    if (node.events[i] !== browser.events[i])
      return `${n}: event #${i} differs (${i} identical before it)\n  node:    ${decode(node.events[i])}\n  browser: ${decode(browser.events[i])}`;
  for (let i = 0; i < Math.max(node.bodies.length, browser.bodies.length); i++)
    if (node.bodies[i] !== browser.bodies[i])
      return `${n}: final body #${i} differs\n  node:    ${decode(node.bodies[i])}\n  browser: ${decode(browser.bodies[i])}`;
  if (node.time !== browser.time)
    return `${n}: final time differs: ${decode(node.time)} vs ${decode(browser.time)}`;
  if (node.result !== browser.result)
    return `${n}: advance result differs: ${node.result} vs ${browser.result}`;
  return null;
}

let server: StaticServer;
let browser: Browser;
let page: Page;
const loaded: string[] = [];
const node = new Map<string, SceneRun>();
let inBrowser: { userAgent: string; origin: string; hasProcess: boolean; runs: SceneRun[] };

beforeAll(async () => {
  ensureEngineBuilt();
  server = await serveStatic(DIST);
  browser = await chromium.launch({
    headless: true,
    executablePath: "/usr/bin/chromium",
    args: ["--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking"],
  });
  page = await browser.newPage();
  page.on("response", (r) => {
    if (r.status() === 200) loaded.push(new URL(r.url()).pathname);
  });
  // An empty page at the server's origin (the dist has no index.html), so "/index.js" resolves there.
  await page.route(`${server.url}blank.html`, (route) =>
    route.fulfill({ contentType: "text/html", body: "<!doctype html><title>engine</title>" }),
  );
  await page.goto(`${server.url}blank.html`);
  for (const scene of SCENES) node.set(scene, runScene(engine, scene));
  // The page script is a string, so no test-side transform touches the dynamic import; the scene
  // function travels as its source text and runs in the page against the module the page fetched.
  inBrowser = await page.evaluate(`(async () => {
    const engine = await import("/index.js");
    const runScene = ${runScene.toString()};
    return {
      userAgent: navigator.userAgent,
      origin: location.origin,
      hasProcess: typeof process !== "undefined",
      runs: ${JSON.stringify(SCENES)}.map((scene) => runScene(engine, scene)),
    };
  })()`);
  const versions = `Node ${process.versions.node} (V8 ${process.versions.v8}) vs Chromium ${browser.version()}`;
  console.log(`engineInBrowser: ${versions}, userAgent ${inBrowser.userAgent}`);
});

afterAll(async () => {
  await browser?.close();
  await server?.close();
});

describe("the engine in Node and in Chromium", () => {
  it("runs in the page from the served dist, not from Node", () => {
    expect(inBrowser.userAgent).toMatch(/Chrom/);
    expect(inBrowser.origin).toBe(server.url.replace(/\/$/, ""));
    expect(inBrowser.hasProcess).toBe(false);
    expect(loaded).toEqual(expect.arrayContaining(["/index.js", "/sim/world.js", "/roots/index.js"]));
    expect(inBrowser.runs.map((r) => r.scene)).toEqual([...SCENES]);
  });

  /** What each scene must do on each side: its advance result, and how many discs end at rest. */
  const expected: Record<string, { result: RegExp; resting: number }> = {
    gas: { result: /^events 4000$/, resting: 0 },
    friction: { result: /^idle \d{4,}$/, resting: 300 },
    pinball: { result: /^events 4000$/, resting: 0 },
    galperin: { result: /^idle 3141$/, resting: 0 },
  };

  it.each(SCENES)("%s: every event and the final state agree bit for bit", (scene) => {
    const n = node.get(scene) as SceneRun;
    const b = inBrowser.runs[SCENES.indexOf(scene)] as SceneRun;
    const want = expected[scene] as (typeof expected)[string];
    // Not vacuous: each side did the work on its own (Galperin's count is exactly 3141).
    for (const run of [n, b]) {
      expect(run.result).toMatch(want.result);
      expect(`${run.events.length}`).toBe(run.result.split(" ")[1]);
      expect(run.resting).toBeGreaterThanOrEqual(want.resting);
    }
    expect(new Set(n.events.map((e) => e.split(" ")[0])).size).toBeGreaterThan(scene === "pinball" ? 2 : 1);
    expect(firstDifference(n, b)).toBeNull();
    console.log(`${scene}: ${n.events.length} events and ${n.bodies.length} bodies identical`);
  });
});
