/**
 * When the ceiling loop's calendar queue (minimalCalendar.mjs) is rebuilt, and with what bucket
 * width: the engine's rules (packages/engine/src/sim/calendarWidth.ts), written again without its
 * API, and ported to the WebAssembly twin (bench/wasm/assembly/calendarWidth.ts) with the same
 * arithmetic in the same order, so both queues choose the same widths bit for bit. Pure functions,
 * off the hot path (a rebuild is rare); constants copied from the engine's tolerances.
 */
/** Copies of packages/engine/src/tolerances.ts (the bench does not import engine internals). */
const CALENDAR_BUCKET_TARGET = 2;
const CALENDAR_REBUILD_FACTOR = 4;

/**
 * Whether the queue should be rebuilt: after 64 bucket advances, when the entries loaded per bucket
 * drift from CALENDAR_BUCKET_TARGET by more than CALENDAR_REBUILD_FACTOR, or when the overflow list
 * was scanned for far more entries than are queued.
 */
export function rebuildDue(advances, loaded, overScanned, queued) {
  if (advances < 64) return false;
  const perBucket = loaded / advances;
  return (
    perBucket > CALENDAR_BUCKET_TARGET * CALENDAR_REBUILD_FACTOR ||
    perBucket < CALENDAR_BUCKET_TARGET / CALENDAR_REBUILD_FACTOR ||
    overScanned > 8 * queued + 1024
  );
}

/**
 * The bucket width for the m queued keys in keys[0..m) whose smallest is lo (reordering keys):
 * CALENDAR_BUCKET_TARGET entries per bucket if the keys are spread like an exponential (median
 * spread 0.69 tau). Not positive, or too small to invert, when the keys are all equal: the caller
 * then keeps its width.
 */
export function widthFor(keys, m, lo) {
  const spread = m > 0 ? select(keys, m, m >> 1) - lo : 0;
  return (CALENDAR_BUCKET_TARGET * spread) / (0.69 * Math.max(1, m));
}

/** The k-th smallest (from 0) of a[0..m), reordering a (Hoare selection). */
function select(a, m, k) {
  let lo = 0;
  let hi = m - 1;
  while (lo < hi) {
    const p = a[(lo + hi) >> 1];
    let i = lo;
    let j = hi;
    while (i <= j) {
      while (a[i] < p) i++;
      while (a[j] > p) j--;
      if (i <= j) {
        const t = a[i];
        a[i] = a[j];
        a[j] = t;
        i++;
        j--;
      }
    }
    if (k <= j) hi = j;
    else if (k >= i) lo = i;
    else break;
  }
  return a[k];
}
