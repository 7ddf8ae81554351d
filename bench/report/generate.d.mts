/** Types of bench/report/generate.mjs (the benchmark report generator), for the tests. */

/** A run's results JSON (bench/results/latest.json); the sections are read by the report modules. */
export interface BenchResults {
  file: string;
  date: string;
  quick?: boolean;
  seconds: number;
  machine: { cpu: string; cores: number; memoryGiB: number; platform: string; node: string; v8: string };
  [section: string]: unknown;
}

/**
 * Writes docs/benchmarks.md, docs/benchmarks-headline.md and docs/bench/*.svg under `root` (default:
 * the repository) and rewrites root/README.md's headline block; returns the written paths relative to
 * root (the README not listed). A full run's results get bench/results/galperin-push.json's rows merged
 * in (the object is changed in place).
 */
export function generate(results: BenchResults, options?: { root?: string }): { files: string[] };
