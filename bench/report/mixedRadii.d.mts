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
/** A row of a gas with many large discs or radii over a range (bench/scenes/polydisperse.mjs). */
export interface ManyRadiiRow {
  law: string;
  n: number;
  batch?: number;
  runs?: number;
  eventsPerSecond?: number;
  error?: string;
}
export function mixedRadiiBlock(
  e: { mixedRadii?: { rows: MixedRadiiRow[]; manyRows?: ManyRadiiRow[]; error?: string } },
  out: string[],
): void;
