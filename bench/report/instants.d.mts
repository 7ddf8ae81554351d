/** Types of bench/report/instants.mjs (the report's rows of a scene built one action per instant), for the tests. */
export interface InstantsRow {
  scene: "resting" | "thrown";
  history: boolean;
  points: { n: number; ms: number; usPerApply?: number; collisions?: number; stops?: number }[];
  scaling: number;
}
export function instantsBlock(
  e: { instants?: { runs?: number; dt?: number; rows?: InstantsRow[]; error?: string } },
  out: string[],
): void;
