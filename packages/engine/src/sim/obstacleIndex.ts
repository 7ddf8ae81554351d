/**
 * Where each line or point sits in the World's list of them (SimState's lineList, pointList), so
 * that an edit finds an obstacle by id without scanning the list, and a scene of m obstacles is
 * built in O(m), not O(m^2).
 *
 * The list's order is the one it always had: the order the obstacles were added in; an update
 * keeps the obstacle's place, a removal keeps the others' order. (No result depends on that order:
 * ties between obstacles go by id, and lists read by users are sorted by id; but the grid is laid
 * out from the list in its order, so it is kept exactly.)
 *
 * A removal leaves its entry in the list, no longer indexed, until `compact` drops the removed
 * entries in one ordered pass: the owner compacts before reading the list whole (a grid rebuild, a
 * placement check, a copy), a read that costs O(m) itself, so a run of k removals costs O(k + m)
 * rather than O(k m). Between a removal and the next compaction the list is read only by id
 * through this index. (A World whose grid holds the obstacles by position compacts at once and
 * renumbers what refers to the positions after the removed one: obstacleUpkeep.ts.)
 */
export class ObstacleIndex<T extends { readonly id: string }> {
  /** Position of each live obstacle's id in the list; null until first needed (a copied list is indexed then). */
  private at: Map<string, number> | null = null;
  /** Removed entries still in the list, and the first one's position. */
  private removed = 0;
  private firstRemoved = 0;

  /** The position map, built from `list` (which holds no removed entry then) when first needed. */
  private positions(list: readonly T[]): Map<string, number> {
    if (this.at === null) {
      this.at = new Map();
      for (let k = 0; k < list.length; k++) this.at.set((list[k] as T).id, k);
    }
    return this.at;
  }

  /** The list was replaced (by a copy with no removed entry): index it afresh when next needed. */
  reset(): void {
    this.at = null;
    this.removed = 0;
  }

  /** Whether an obstacle with this id is in the list (and not removed). */
  has(list: readonly T[], id: string): boolean {
    return this.positions(list).has(id);
  }

  /** The obstacle with this id, if any. */
  get(list: readonly T[], id: string): T | undefined {
    const k = this.positions(list).get(id);
    return k === undefined ? undefined : list[k];
  }

  /** Position of the obstacle with this id in the list (-1: none). */
  indexOf(list: readonly T[], id: string): number {
    return this.positions(list).get(id) ?? -1;
  }

  /** Append `item` (its id must not be in the list). */
  add(list: T[], item: T): void {
    this.positions(list).set(item.id, list.length);
    list.push(item);
  }

  /** Put `item` in the place of the obstacle with the same id (which must be in the list). */
  replace(list: T[], item: T): void {
    list[this.positions(list).get(item.id) as number] = item;
  }

  /** Remove the obstacle with this id (which must be in the list); `compact` drops its entry. */
  remove(list: readonly T[], id: string): void {
    const at = this.positions(list);
    const k = at.get(id) as number;
    at.delete(id);
    if (this.removed === 0 || k < this.firstRemoved) this.firstRemoved = k;
    this.removed++;
  }

  /** Drop the removed entries from `list`, keeping the order of the others. O(1) when there are none. */
  compact(list: T[]): void {
    if (this.removed === 0) return;
    const at = this.positions(list);
    // Entries before the first removed one keep their places.
    let w = this.firstRemoved;
    for (let k = w; k < list.length; k++) {
      const item = list[k] as T;
      // A removed entry is no longer indexed at its position (its id may live on elsewhere: re-added).
      if (at.get(item.id) !== k) continue;
      if (w !== k) {
        list[w] = item;
        at.set(item.id, w);
      }
      w++;
    }
    list.length = w;
    this.removed = 0;
  }
}
