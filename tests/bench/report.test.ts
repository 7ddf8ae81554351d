/**
 * The committed benchmark report — docs/benchmarks.md, docs/benchmarks-headline.md, docs/bench/*.svg
 * and the README's headline block — is byte for byte what bench/report/generate.mjs makes from the
 * committed bench/results/latest.json (and bench/results/galperin-push.json, which it merges). A change
 * to the generator or to latest.json that was not followed by regenerating the report fails here.
 */
import { copyFileSync, mkdtempSync, readdirSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { afterAll, describe, expect, it } from "vitest";
import { type BenchResults, generate } from "../../bench/report/generate.mjs";

const ROOT = join(dirname(fileURLToPath(import.meta.url)), "..", "..");
const RERUN =
  "the committed report differs from what the generator makes from bench/results/latest.json: rerun node bench/report/generate.mjs and commit docs/benchmarks.md, docs/benchmarks-headline.md, docs/bench/ and README.md";

const dirs: string[] = [];
afterAll(() => {
  for (const d of dirs) rmSync(d, { recursive: true, force: true });
});

const committedResults = (): BenchResults =>
  JSON.parse(readFileSync(join(ROOT, "bench", "results", "latest.json"), "utf8")) as BenchResults;

/** Generates the report into a fresh temporary root holding a copy of the README. */
function generateIntoTemp(results: BenchResults): { root: string; files: string[] } {
  const root = mkdtempSync(join(tmpdir(), "chapgame-report-"));
  dirs.push(root);
  copyFileSync(join(ROOT, "README.md"), join(root, "README.md"));
  return { root, files: generate(results, { root }).files };
}

const svgNames = (root: string): string[] =>
  readdirSync(join(root, "docs", "bench"))
    .filter((f) => f.endsWith(".svg"))
    .sort();

/** Where two texts first differ, as "line N: committed … / generated …". */
function firstDifference(committed: string, generated: string): string {
  const a = committed.split("\n");
  const b = generated.split("\n");
  for (let i = 0; i < Math.max(a.length, b.length); i++)
    if (a[i] !== b[i])
      return `line ${i + 1}: committed ${JSON.stringify(a[i]?.slice(0, 160))} / generated ${JSON.stringify(b[i]?.slice(0, 160))}`;
  return "same lines (line endings or encoding differ)";
}

/** Every generated file (and the README) that is not byte-identical to the repository's, described. */
function differences(root: string, files: string[]): string[] {
  const out: string[] = [];
  const committedSvgs = svgNames(ROOT);
  const generatedSvgs = svgNames(root);
  for (const f of committedSvgs)
    if (!generatedSvgs.includes(f)) out.push(`docs/bench/${f}: committed but no longer generated`);
  for (const f of [...files, "README.md"]) {
    const generated = readFileSync(join(root, f));
    let committed: Buffer;
    try {
      committed = readFileSync(join(ROOT, f));
    } catch {
      out.push(`${f}: generated but not in the repository`);
      continue;
    }
    if (!committed.equals(generated))
      out.push(`${f}: ${firstDifference(committed.toString("utf8"), generated.toString("utf8"))}`);
  }
  return out;
}

describe("committed benchmark report", () => {
  it("is exactly what bench/report/generate.mjs makes from bench/results/latest.json", () => {
    const { root, files } = generateIntoTemp(committedResults());
    expect(files).toContain("docs/benchmarks.md");
    expect(files).toContain("docs/benchmarks-headline.md");
    expect(files.filter((f) => f.startsWith("docs/bench/")).length).toBeGreaterThan(0);
    expect(differences(root, files), RERUN).toEqual([]);
  });

  it("the comparison catches a changed number (the headline's solver time doubled)", () => {
    const results = committedResults();
    const solver = results.solver as { random: { methods: { id: string; nsPerCall: number }[] } };
    const rr = solver.random.methods.find((m) => m.id === "realRoots");
    expect(rr, "latest.json has a realRoots row").toBeDefined();
    if (rr) rr.nsPerCall *= 2;
    const { root, files } = generateIntoTemp(results);
    const found = differences(root, files).map((d) => d.split(":")[0]);
    expect(found.sort()).toEqual(
      ["README.md", "docs/bench/solver.svg", "docs/benchmarks-headline.md", "docs/benchmarks.md"].sort(),
    );
  });

  it("states the process counts and Galperin's target that the results record, not fixed words", () => {
    const results = committedResults();
    const engine = results.engine as {
      scaling: { processesPerN: number };
      galperin7: { seconds: number; targetSeconds?: number };
      ablations: { processes: string }[];
    };
    engine.scaling.processesPerN = 5;
    engine.galperin7.targetSeconds = engine.galperin7.seconds / 2;
    for (const a of engine.ablations) a.processes = "1 alternating pairs, one per configuration";
    const { root } = generateIntoTemp(results);
    const report = readFileSync(join(root, "docs", "benchmarks.md"), "utf8");
    const headline = readFileSync(join(root, "docs", "benchmarks-headline.md"), "utf8");
    expect(report).toContain("five per N in this run");
    expect(report).toContain("On and off alternate over one process pair in this run");
    const target = `< ${engine.galperin7.targetSeconds} s`;
    expect(report).toContain(`(target ${target}): **missed**`);
    expect(headline).toMatch(new RegExp(`${target}, exact count \\| \\*\\*missed\\*\\*`));
  });
});
