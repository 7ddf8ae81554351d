/**
 * Report generator: results JSON → docs/benchmarks.md, docs/bench/*.svg and
 * docs/benchmarks-headline.md, and the README's headline block between its markers. Nothing in the
 * report is typed by hand: every number comes from the JSON; the prose in the section modules only
 * names what was measured and the fixed caveats of the method.
 * generate(results, { root }) writes those files under `root` (default: the repository) and returns
 * { files } (paths relative to root, the README not listed); a full run's results first get the rows
 * of bench/results/galperin-push.json merged in (galperinPush.mjs).
 * Modules: document.mjs assembles headline.mjs, solver.mjs, peers.mjs, engine.mjs (with ablations.mjs,
 * timeline.mjs) and stress.mjs (with galperinPush.mjs); format.mjs and svg.mjs are the helpers.
 * Usage: node bench/report/generate.mjs [results.json]   (default bench/results/latest.json)
 */
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { buildReport, headlineFile, readmeBlock } from "./document.mjs";
import { mergePush } from "./galperinPush.mjs";

const ROOT = join(dirname(fileURLToPath(import.meta.url)), "..", "..");

export function generate(results, { root = ROOT } = {}) {
  if (!results.quick) mergePush(results, join(ROOT, "bench", "results", "galperin-push.json"));
  const { markdown, head, svgs } = buildReport(results);
  const dir = join(root, "docs", "bench");
  mkdirSync(dir, { recursive: true });
  for (const f of readdirSync(dir)) if (f.endsWith(".svg")) rmSync(join(dir, f));
  for (const [f, text] of Object.entries(svgs)) writeFileSync(join(root, "docs", "bench", f), `${text}\n`);
  writeFileSync(join(root, "docs", "benchmarks.md"), markdown);
  writeFileSync(join(root, "docs", "benchmarks-headline.md"), headlineFile(results, head));
  // The README carries the same headline between markers, rewritten here (never typed by hand).
  const readme = join(root, "README.md");
  if (existsSync(readme)) {
    const text = readFileSync(readme, "utf8");
    const start = "<!-- bench-headline:start -->";
    const end = "<!-- bench-headline:end -->";
    const i = text.indexOf(start);
    const j = text.indexOf(end);
    if (i >= 0 && j > i)
      writeFileSync(
        readme,
        `${text.slice(0, i + start.length)}\n${readmeBlock(results, head)}\n${text.slice(j)}`,
      );
  }
  return {
    files: [
      "docs/benchmarks.md",
      "docs/benchmarks-headline.md",
      ...Object.keys(svgs).map((f) => `docs/bench/${f}`),
    ],
  };
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const file = process.argv[2] ?? join(ROOT, "bench", "results", "latest.json");
  const r = generate(JSON.parse(readFileSync(file, "utf8")));
  console.log(`wrote ${r.files.length} files`);
}
