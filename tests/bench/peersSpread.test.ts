/**
 * The side-by-side rows' spread in the report: when a run records its timed passes' extremes and its
 * pass limits (bench/peers/run.mjs since the rows are settled), the headline's dilute-gas row and the
 * scene tables give "median (fastest–slowest)", and the caveat states the limits the run used; the
 * committed results without those fields keep the bare median and say how they were taken.
 */
import { copyFileSync, mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { afterAll, describe, expect, it } from "vitest";
import { PASS_LIMITS } from "../../bench/lib/settledPasses.mjs";
import { msRange } from "../../bench/report/format.mjs";
import { type BenchResults, generate } from "../../bench/report/generate.mjs";

const ROOT = join(dirname(fileURLToPath(import.meta.url)), "..", "..");
const dirs: string[] = [];
afterAll(() => {
  for (const d of dirs) rmSync(d, { recursive: true, force: true });
});

interface Row {
  ns: number;
  runs: number;
  minNs?: number;
  maxNs?: number;
  peer?: string;
  hz?: number;
  config?: string;
}
interface Peers {
  passLimits?: typeof PASS_LIMITS;
  scenes: { id: string; chapgame: Row; peers: Row[] }[];
}

const committed = (): BenchResults =>
  JSON.parse(readFileSync(join(ROOT, "bench", "results", "latest.json"), "utf8")) as BenchResults;

function report(results: BenchResults): { headline: string; full: string } {
  const root = mkdtempSync(join(tmpdir(), "chapgame-spread-"));
  dirs.push(root);
  copyFileSync(join(ROOT, "README.md"), join(root, "README.md"));
  generate(results, { root });
  return {
    headline: readFileSync(join(root, "docs", "benchmarks-headline.md"), "utf8"),
    full: readFileSync(join(root, "docs", "benchmarks.md"), "utf8"),
  };
}

/** Drops what a settled run records beyond the median (bench/lib/settledPasses.mjs). */
function withoutSpread(row: Row): void {
  const r = row as unknown as Record<string, unknown>;
  for (const k of ["minNs", "q1Ns", "q3Ns", "maxNs", "passesNs", "warmup", "metricsPassNs"]) delete r[k];
}

const gasRow = (h: string) => h.split("\n").find((l) => l.startsWith("| dilute gas, 1,000 discs")) ?? "";

describe("side-by-side spread in the report", () => {
  it("gives the median with the fastest and slowest pass when the run recorded them", () => {
    const results = committed();
    const peers = results.peers as Peers;
    peers.passLimits = PASS_LIMITS;
    const gas = peers.scenes.find((s) => s.id === "dilute-gas");
    if (!gas) throw new Error("the committed results have no dilute-gas scene");
    Object.assign(gas.chapgame, { ns: 4.31e6, runs: 15, minNs: 4.1e6, maxNs: 5.26e6 });
    for (const p of gas.peers) Object.assign(p, { minNs: p.ns * 0.9, maxNs: p.ns * 1.5, runs: 4 });
    const fastest = gas.peers
      .filter((p) => p.hz === 60 && p.config === "tuned")
      .sort((a, b) => a.ns - b.ns)[0];
    if (!fastest) throw new Error("the committed results have no tuned 60 Hz peer row for the dilute gas");
    const { headline, full } = report(results);
    const row = gasRow(headline);
    expect(row).toContain("| 4.31 ms (4.1–5.26), ΔE/E");
    const lo = Number((fastest.ns * 0.9e-6).toPrecision(3));
    const hi = Number((fastest.ns * 1.5e-6).toPrecision(3));
    expect(row).toContain(`${fastest.peer} ${Number((fastest.ns / 1e6).toPrecision(3))} ms (${lo}–${hi})`);
    expect(full).toContain("| **chapgame** | exact | 1,903 events | 4.31 ms (4.1–5.26) | 15 |");
    expect(full).toContain(
      `until the median of the last ${PASS_LIMITS.settleWindow} is within 20 % of the fastest (at most 0.25 s or ${PASS_LIMITS.maxWarmup} passes; a metrics pass of 0.5 s or more stands for the warm-up), then at least ${PASS_LIMITS.minRuns} timed passes (up to ${PASS_LIMITS.maxRuns} while they total under 0.2 s)`,
    );
  });

  it("keeps the bare median for results without the spread, and says they were not settled", () => {
    const results = committed();
    const peers = results.peers as Peers;
    // Results from before the rows were settled (session 29) carry none of the spread's fields.
    delete peers.passLimits;
    for (const scene of peers.scenes) for (const row of [scene.chapgame, ...scene.peers]) withoutSpread(row);
    const gas = peers.scenes.find((s) => s.id === "dilute-gas");
    const { headline, full } = report(results);
    const row = gasRow(headline);
    expect(row).toContain(`| ${Number(((gas?.chapgame.ns ?? 0) / 1e6).toPrecision(3))} ms, ΔE/E`);
    expect(row).not.toMatch(/ms \(/);
    expect(full).toContain("These rows were timed before the side-by-side timings were settled");
  });

  it("never prints a median outside its printed range", () => {
    // Session 30's rapier2d-compat row: median 100.75 ms in 92.38–101.50, once printed "101 ms (92–100)".
    expect(msRange({ ns: 100_750_229, minNs: 92_379_622, maxNs: 101_503_402, runs: 3 })).toBe(
      "101 ms (92.4–102)",
    );
    expect(msRange({ ns: 283_074_771, minNs: 281_109_018, maxNs: 283_738_755, runs: 3 })).toBe(
      "283 ms (281–284)",
    );
    expect(msRange({ ns: 4_740_000, runs: 1 })).toBe("4.74 ms");
  });
});
