/**
 * When the WebAssembly calendar queue (calendar.ts) is rebuilt, and with what bucket width: the port
 * of bench/engine/minimalCalendarWidth.mjs (the engine's calendarWidth.ts rules), the same
 * arithmetic in the same order, so both queues choose the same widths bit for bit. Pure functions,
 * off the hot path (a rebuild is rare); Binaryen compiles them into the one module.
 */
/** Copies of packages/engine/src/tolerances.ts (the bench does not import engine internals). */
const CALENDAR_BUCKET_TARGET: f64 = 2;
const CALENDAR_REBUILD_FACTOR: f64 = 4;

/**
 * Whether the queue should be rebuilt: after 64 bucket advances, when the entries loaded per bucket
 * drift from CALENDAR_BUCKET_TARGET by more than CALENDAR_REBUILD_FACTOR, or when the overflow list
 * was scanned for far more entries than are queued.
 */
export function rebuildDue(advances: i32, loaded: i32, overScanned: i32, queued: i32): bool {
  if (advances < 64) return false;
  const perBucket = <f64>loaded / <f64>advances;
  return (
    perBucket > CALENDAR_BUCKET_TARGET * CALENDAR_REBUILD_FACTOR ||
    perBucket < CALENDAR_BUCKET_TARGET / CALENDAR_REBUILD_FACTOR ||
    overScanned > 8 * queued + 1024
  );
}

/**
 * The bucket width for the m queued keys in keys[0..m) whose smallest is lo (reordering keys), as
 * minimalCalendarWidth.mjs's widthFor: not positive, or too small to invert, when the keys are all
 * equal (the caller then keeps its width).
 */
export function widthFor(keys: StaticArray<f64>, m: i32, lo: f64): f64 {
  const spread: f64 = m > 0 ? select(keys, m, m >> 1) - lo : 0;
  return (CALENDAR_BUCKET_TARGET * spread) / (0.69 * <f64>max(1, m));
}

/** The k-th smallest (from 0) of a[0..m), reordering a (Hoare selection). */
function select(a: StaticArray<f64>, m: i32, k: i32): f64 {
  let lo = 0;
  let hi = m - 1;
  while (lo < hi) {
    const p = unchecked(a[(lo + hi) >> 1]);
    let i = lo;
    let j = hi;
    while (i <= j) {
      while (unchecked(a[i]) < p) i++;
      while (unchecked(a[j]) > p) j--;
      if (i <= j) {
        const t = unchecked(a[i]);
        unchecked((a[i] = unchecked(a[j])));
        unchecked((a[j] = t));
        i++;
        j--;
      }
    }
    if (k <= j) hi = j;
    else if (k >= i) lo = i;
    else break;
  }
  return unchecked(a[k]);
}
