/** Types of bench/report/mixedRadii.mjs (the report's mixed-radii rows), for the tests. */
export interface MixedRadiiRow {
  bigR: number;
  n: number;
  batch?: number;
  runs?: number;
  eventsPerSecond?: number;
  bigEventShare?: number;
  error?: string;
}
export function mixedRadiiBlock(
  e: { mixedRadii?: { rows: MixedRadiiRow[]; error?: string } },
  out: string[],
): void;
