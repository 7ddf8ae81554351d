/**
 * Test helpers that watch the scene a test editor's host shows: how many copies of an action it
 * holds, and a promise that resolves once the scene changes (a change's apply was handled and its
 * check runs).
 */
import type { Action } from "../engineTypes";
import type { testEditor } from "./harness";

type Harness = ReturnType<typeof testEditor>;

/** How many actions of the current scene are `a` (same time, type and id). */
export function count(h: Harness, a: Action): number {
  const doc = h.client.getSnapshot().doc!;
  const id = (x: Action) => ("id" in x ? x.id : null);
  return doc.actions.filter((x) => x.time === a.time && x.type === a.type && id(x) === id(a)).length;
}

/** Resolves once the host shows a changed scene (a change's check runs); call before the change. */
export function checking(h: Harness): Promise<void> {
  const rev = h.client.getSnapshot().docRevision;
  return new Promise((resolve) => {
    const stop = h.client.subscribe(() => {
      if (h.client.getSnapshot().docRevision === rev) return;
      stop();
      resolve();
    });
  });
}
