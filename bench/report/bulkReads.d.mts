/** Types of bench/report/bulkReads.mjs (the report's bulk-read rows), for the tests. */
export interface BulkReadRow {
  api: "Timeline" | "World";
  order: "forwards" | "backwards" | "now";
  objectsNs: number;
  arraysNs: number;
}
export function bulkReadsBlock(
  e: {
    bulkReads?: {
      bodies?: number;
      events?: number;
      horizon?: number;
      reads?: number;
      passes?: number;
      rows?: BulkReadRow[];
      allocation?: { stateAt: number; bodyArraysAt: number; bodies: number; bodyArrays: number };
      error?: string;
    };
  },
  out: string[],
): void;
