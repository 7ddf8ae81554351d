/**
 * Which action an "action" entry of the event log is: its index in the timeline's `actions` (the
 * scene's action list, in time order). Actions apply in time order, then in list order, and each
 * applied action logs one entry (the engine's actionGroup.ts), so the k-th action entry logged at
 * time T is the k-th action of the list with time T. withActionIndices needs every entry logged at
 * each time it holds (what eventsBetween returns), never a page cut inside a group of entries at one
 * time.
 */
import type { Action, LogEvent } from "../engineTypes";
import type { PageEvent } from "./protocol";

/** Index of the first action with time >= t in `actions` (sorted by time). */
function firstAtOrAfter(actions: readonly Action[], t: number): number {
  let lo = 0;
  let hi = actions.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if ((actions[mid] as Action).time < t) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/**
 * Copies of the entries of `events` (complete groups per time, in log order) that `keep` keeps
 * (given each entry and its position in `events`), each action entry with `actionIndex` (left out
 * when the list does not hold a matching action: same time, type and id). `actions` is read only
 * when `events` holds an action entry.
 */
export function withActionIndices(
  events: readonly LogEvent[],
  actions: () => readonly Action[],
  keep: (e: LogEvent, i: number) => boolean = () => true,
): PageEvent[] {
  let list: readonly Action[] | null = null;
  let groupTime = Number.NaN;
  let next = 0;
  const out: PageEvent[] = [];
  for (const [k, e] of events.entries()) {
    let index: number | undefined;
    if (e.type === "action") {
      list ??= actions();
      if (e.time !== groupTime) {
        groupTime = e.time;
        next = firstAtOrAfter(list, e.time);
      }
      const i = next++;
      const a = list[i];
      const id = a !== undefined && "id" in a ? a.id : undefined;
      if (a !== undefined && a.time === e.time && a.type === e.action && id === e.ids[0]) index = i;
    }
    if (!keep(e, k)) continue;
    // a copy of the entry's own fields (its ids too), whatever else the object carries
    const copy = {
      time: e.time,
      type: e.type,
      ids: [...e.ids],
      point: e.point,
      normal: e.normal,
      impulse: e.impulse,
      ...(e.action === undefined ? {} : { action: e.action }),
    };
    const c = copy as PageEvent; // the same type and fields as e
    if (index !== undefined) c.actionIndex = index;
    out.push(c);
  }
  return out;
}

/**
 * `scene` with its actions in the order they apply (time, then list order: a stable sort), the
 * same list when it is in that order already. The engine names a refused action by its index in
 * the list it was given, and the scene the editor shows (Timeline.toScene) lists them in applying
 * order: a file whose actions are not in time order would otherwise have its refused action named
 * by an index that is another action's in the editor's scene (the host loads every scene so).
 */
export function inApplyingOrder<S extends { actions: readonly Action[] }>(scene: S): S {
  const a = scene.actions;
  if (a.every((x, i) => i === 0 || (a[i - 1] as Action).time <= x.time)) return scene;
  const order = a.map((_, i) => i).sort((i, j) => (a[i] as Action).time - (a[j] as Action).time || i - j);
  return { ...scene, actions: order.map((i) => a[i] as Action) };
}
