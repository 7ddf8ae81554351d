/**
 * End-to-end harness: builds the editor when its dist is missing, serves it, launches Debian's
 * Chromium through playwright-core with a fresh profile, and offers user-level helpers
 * (play, pause, scrubTo, time, ...) that drive the editor by its accessible names.
 */
import { execFileSync } from "node:child_process";
import { existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync, statSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { type BrowserContext, chromium, type Page } from "playwright-core";
import { type StaticServer, serveStatic } from "./server.js";

export const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
/** The built editor; CHAPGAME_E2E_DIST serves another build as it is (to measure an older version). */
export const DIST = process.env.CHAPGAME_E2E_DIST || join(ROOT, "packages/editor/dist");
export const ARTIFACTS = join(ROOT, "test-artifacts");

/** Newest modification time (ms) of the files under `path`. */
function newest(path: string): number {
  if (!existsSync(path)) return 0;
  const st = statSync(path);
  if (!st.isDirectory()) return st.mtimeMs;
  let m = st.mtimeMs;
  for (const name of readdirSync(path)) m = Math.max(m, newest(join(path, name)));
  return m;
}

/** Builds the editor when its dist is missing or older than its sources (editor, engine, public). */
export function ensureBuilt(): void {
  if (process.env.CHAPGAME_E2E_DIST) return;
  const index = join(DIST, "index.html");
  const sources = [
    "packages/editor/src",
    "packages/editor/index.html",
    "packages/editor/vite.config.ts",
    "packages/engine/src",
    "public",
  ];
  const built = existsSync(index) ? statSync(index).mtimeMs : 0;
  if (built > 0 && sources.every((p) => newest(join(ROOT, p)) < built)) return;
  // NODE_ENV=production: vitest sets NODE_ENV=test, and Vite then bundles React's development build
  // (half again as large, and several times slower to render: tables took 60-80 ms long tasks).
  execFileSync("npx", ["vite", "build"], {
    cwd: join(ROOT, "packages/editor"),
    stdio: "inherit",
    env: { ...process.env, NODE_ENV: "production" },
  });
}

/** The window size openEditor opens with (CSS px), when not given another. */
export const DEFAULT_WINDOW = { width: 1400, height: 900 } as const;

export interface Session {
  url: string;
  context: BrowserContext;
  page: Page;
  close(): Promise<void>;
}

export async function openEditor(options: { width?: number; height?: number } = {}): Promise<Session> {
  ensureBuilt();
  mkdirSync(ARTIFACTS, { recursive: true });
  const server: StaticServer = await serveStatic(DIST);
  const userDataDir = mkdtempSync(join(tmpdir(), "chapgame-e2e-"));
  const context = await chromium.launchPersistentContext(userDataDir, {
    headless: true,
    executablePath: "/usr/bin/chromium",
    args: [
      "--no-sandbox",
      "--disable-gpu",
      "--disable-quic",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
    ],
    viewport: {
      width: options.width ?? DEFAULT_WINDOW.width,
      height: options.height ?? DEFAULT_WINDOW.height,
    },
  });
  const page = context.pages()[0] ?? (await context.newPage());
  await page.goto(server.url);
  await page.getByRole("slider", { name: "Time" }).waitFor();
  return {
    url: server.url,
    context,
    page,
    async close() {
      await context.close();
      await server.close();
      rmSync(userDataDir, { recursive: true, force: true });
    },
  };
}

export async function screenshot(page: Page, name: string): Promise<void> {
  await page.screenshot({ path: join(ARTIFACTS, `${name}.png`) });
}

/** The current time shown by the `Time` slider. */
export async function currentTime(page: Page): Promise<number> {
  return Number(await page.getByRole("slider", { name: "Time" }).inputValue());
}

/** The horizon, as the `Time` slider's max (the slider spans the whole history unless zoomed). */
export async function horizon(page: Page): Promise<number> {
  return Number(await page.getByRole("slider", { name: "Time" }).getAttribute("max"));
}

/** Moves the `Time` slider to t like a user typing a value (fires input/change). */
export async function scrubTo(page: Page, t: number): Promise<void> {
  await page.getByRole("slider", { name: "Time" }).fill(String(t));
}

export async function waitFor(check: () => Promise<boolean>, timeoutMs = 10_000): Promise<void> {
  const end = Date.now() + timeoutMs;
  while (!(await check())) {
    if (Date.now() > end) throw new Error("timed out waiting for a condition");
    await new Promise((r) => setTimeout(r, 50));
  }
}
