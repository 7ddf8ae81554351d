/** Types of bench/report/obstacles.mjs (the report's obstacle-heavy rows), for the tests. */
export interface ObstacleRow {
  kind: string;
  discs: number;
  obstacles: number;
  batch?: number;
  runs?: number;
  usPerEvent?: number;
  eventsPerSecond?: number;
  cells?: number | null;
  cellSide?: number | null;
  offBatch?: number;
  offUsPerEvent?: number;
  sameAsOff?: boolean;
  buildMs?: number;
  buildUsPerObstacle?: number;
  error?: string;
}
export function obstaclesBlock(
  e: { obstacles?: { rows: ObstacleRow[]; error?: string } },
  out: string[],
): void;
