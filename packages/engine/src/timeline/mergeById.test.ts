/**
 * mergeById (keyframeDelta.ts): the live order after bodies were added, merged into the order sorted
 * before, is the order a sort of every live id gives (keyframes and the World rebuilt from them
 * depend on it, bit for bit).
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { mergeById } from "./keyframeDelta.js";
import { seedFor } from "./testSupport.js";

/** Numbers of `live` (body numbers naming ids[n]) sorted by id, by a sort of every id. */
function sortedOf(live: readonly number[], ids: readonly string[]): number[] {
  return [...live].sort((p, q) => ((ids[p] as string) < (ids[q] as string) ? -1 : 1));
}

describe("mergeById", () => {
  it("merges the added bodies where a sort of every id puts them", () => {
    fc.assert(
      fc.property(
        fc.uniqueArray(fc.string({ maxLength: 4 }), { minLength: 0, maxLength: 40 }),
        fc.nat(),
        (ids, split) => {
          const all = ids.map((_, n) => n);
          const cut = ids.length === 0 ? 0 : split % (ids.length + 1);
          const before = Uint32Array.from(sortedOf(all.slice(0, cut), ids));
          const merged = mergeById(before, all.slice(cut).reverse(), ids);
          expect([...merged]).toStrictEqual(sortedOf(all, ids));
          expect(merged).not.toBe(before); // (keyframes share the old order: never changed)
        },
      ),
      { seed: seedFor("mergeById"), numRuns: 300 },
    );
  });

  it("keeps the order when nothing was added, and takes ids a plain comparison orders (case, digits)", () => {
    const ids = ["b10", "B", "a", "b9", "é", "b1"];
    const before = Uint32Array.from(sortedOf([0, 2, 4], ids));
    expect([...mergeById(before, [], ids)]).toStrictEqual([...before]);
    expect([...mergeById(before, [5, 1, 3], ids)].map((n) => ids[n])).toStrictEqual([...ids].sort());
  });
});
