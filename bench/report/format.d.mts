/** Types of bench/report/format.mjs (the report's number formatting), for the tests. */
export function sig(v: number | null | undefined, digits?: number): string;
export function msRange(
  row: { ns: number; runs: number; minNs?: number; maxNs?: number } | undefined,
): string;
