/** Types of bench/report/instants.mjs (the report's rows of a scene built one action per instant), for the tests. */
export interface InstantsRow {
  scene: "resting" | "thrown";
  history: boolean;
  points: { n: number; ms: number; usPerApply?: number; collisions?: number; stops?: number }[];
  scaling: number;
}
/** Reads over a history built one disc per instant: ms per call of each way at one N. */
export interface InstantReadsRow {
  n: number;
  events: number;
  historyBytes: number;
  ways: { name: string; order: string; ms: number }[];
}
export function instantsBlock(
  e: {
    instants?: {
      runs?: number;
      dt?: number;
      rows?: InstantsRow[];
      reads?: { count: number; passes: number; rows: InstantReadsRow[] };
      error?: string;
    };
  },
  out: string[],
): void;
