/**
 * The order in which tables list ids: natural order, runs of digits inside ids compared by value
 * ("ball2" before "ball10", "d9" before "d100"), other characters by code unit (the same in every
 * locale). The frame lists bodies, lines and points by plain string order; a table asks here for
 * the indices to show them in (the Bodies table) or for its rows in that order (Lines, Points). The order of an ids array is computed once (frames whose bodies are unchanged share one
 * ids array); a plain comparator keeps that to tens of milliseconds at 45,000 bodies.
 */
const cache = new WeakMap<readonly string[], number[]>();

const isDigit = (c: number) => c >= 48 && c <= 57;

/** Natural comparison of two ids (ties broken by plain string order, so the order is total). */
export function compareIds(a: string, b: string): number {
  let i = 0;
  let j = 0;
  while (i < a.length && j < b.length) {
    const ca = a.charCodeAt(i);
    const cb = b.charCodeAt(j);
    if (isDigit(ca) && isDigit(cb)) {
      let si = i;
      while (si < a.length && a.charCodeAt(si) === 48) si++;
      let sj = j;
      while (sj < b.length && b.charCodeAt(sj) === 48) sj++;
      let ei = si;
      while (ei < a.length && isDigit(a.charCodeAt(ei))) ei++;
      let ej = sj;
      while (ej < b.length && isDigit(b.charCodeAt(ej))) ej++;
      if (ei - si !== ej - sj) return ei - si - (ej - sj); // more digits: a larger number
      for (let k = 0; k < ei - si; k++) {
        const d = a.charCodeAt(si + k) - b.charCodeAt(sj + k);
        if (d !== 0) return d;
      }
      i = ei;
      j = ej;
      continue;
    }
    if (ca !== cb) return ca - cb;
    i++;
    j++;
  }
  const rest = a.length - i - (b.length - j);
  if (rest !== 0) return rest;
  return a < b ? -1 : a > b ? 1 : 0;
}

/** Indices of `ids` in natural order. */
export function naturalOrder(ids: readonly string[]): number[] {
  let order = cache.get(ids);
  if (!order) {
    order = ids.map((_, i) => i).sort((i, j) => compareIds(ids[i]!, ids[j]!));
    cache.set(ids, order);
  }
  return order;
}

const itemsCache = new WeakMap<readonly { readonly id: string }[], readonly { readonly id: string }[]>();

/** `items` (lines, points) in the natural order of their ids: the same array object for the same
 *  array (the Lines and Points tables list "p2" before "p10", as the Bodies table lists bodies). */
export function inNaturalOrder<T extends { readonly id: string }>(items: readonly T[]): readonly T[] {
  let sorted = itemsCache.get(items) as readonly T[] | undefined;
  if (!sorted) {
    sorted = [...items].sort((a, b) => compareIds(a.id, b.id));
    itemsCache.set(items, sorted);
  }
  return sorted;
}
