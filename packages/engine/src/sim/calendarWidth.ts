/**
 * The calendar queue's width (calendarQueue.ts), pure functions of its counters and keys: whether
 * the buckets have drifted far enough from their target to pay for a rebuild, and the bucket width
 * and ring length a rebuild chooses. Only speed depends on them: the queue pops in (key, tie order)
 * order whatever the width.
 *
 * The width adapts: a new queue is sized at its first peek from every key queued so far; then every
 * half turn of the ring the queue compares the entries it loaded per bucket with its target and,
 * far off, rebuilds with a width estimated from the keys in the queue; a front that grows for long
 * without the window moving does the same (calendarQueue.ts FRONT_CROWDED).
 */
import { CALENDAR_BUCKET_TARGET, CALENDAR_REBUILD_FACTOR } from "../tolerances.js";

/**
 * Whether a queue of n entries that moved its window `advances` buckets, loading `loaded` entries
 * from them and scanning `overScanned` overflow entries, is far enough from its target to rebuild:
 * the entries per bucket off CALENDAR_BUCKET_TARGET by more than CALENDAR_REBUILD_FACTOR either
 * way (after 64 buckets at least), or the overflow scanned more than 8 times over.
 */
export function rebuildDue(advances: number, loaded: number, overScanned: number, n: number): boolean {
  if (advances < 64) return false;
  const perBucket = loaded / advances;
  return (
    perBucket > CALENDAR_BUCKET_TARGET * CALENDAR_REBUILD_FACTOR ||
    perBucket < CALENDAR_BUCKET_TARGET / CALENDAR_REBUILD_FACTOR ||
    overScanned > 8 * n + 1024
  );
}

/**
 * The bucket width for the queued keys, sorted ascending: about CALENDAR_BUCKET_TARGET entries per
 * bucket near the earliest, if the keys ahead are spread like those queued. 0 when the keys give
 * no usable width (all equal, or a width whose inverse is not finite): the queue keeps its own.
 */
export function bucketWidth(sortedKeys: Float64Array): number {
  const n = sortedKeys.length;
  const lo = sortedKeys[0] ?? 0;
  // The median spread ahead of the earliest key: with keys spread like an exponential of mean
  // tau, the median is 0.69 tau and about n / tau entries fall due per unit of time.
  const spread = (sortedKeys[n >> 1] ?? lo) - lo;
  const w = (CALENDAR_BUCKET_TARGET * spread) / (0.69 * Math.max(1, n));
  return w > 0 && Number.isFinite(1 / w) ? w : 0;
}

/** The ring's length for n entries: a power of two, at least 16 and at least 2 n. */
export function ringLength(n: number): number {
  let nb = 16;
  while (nb < 2 * n) nb *= 2;
  return nb;
}
