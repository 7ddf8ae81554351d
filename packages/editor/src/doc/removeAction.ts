/**
 * Removing one action from a scene's action list, named by its index and checked against what the
 * caller saw (an Event-log entry read earlier: the scene may have changed since). Pure; refuses
 * (throws a message) when the list no longer holds that action at that index.
 */
import type { SceneFile } from "../engineTypes";
import { describeEntry } from "./actionRefs";

/** What an Event-log entry says of its action: its time, type and id (null for setGlobal). */
export interface ActionEntry {
  time: number;
  type: string;
  id: string | null;
}

/** The scene without `actions[index]`; throws a message unless that action is `entry`'s. */
export function withoutAction(scene: SceneFile, index: number, entry: ActionEntry): SceneFile {
  const a = scene.actions[index];
  const id = a !== undefined && "id" in a ? a.id : null;
  if (a === undefined || a.time !== entry.time || a.type !== entry.type || id !== entry.id) {
    const what = describeEntry(entry.type, entry.id);
    const t = Number(entry.time.toPrecision(6));
    // A second click on the ✕ of an entry just removed said "try again" (audit of session 15).
    const same = (b: (typeof scene.actions)[number]) =>
      b.time === entry.time && b.type === entry.type && ("id" in b ? b.id : null) === entry.id;
    if (!scene.actions.some(same))
      throw new Error(`${what} at t = ${t} s is no longer in the scene: nothing was removed.`);
    throw new Error(
      `The scene changed since the Event log listed ${what} at t = ${t} s: nothing was removed (try again).`,
    );
  }
  return { ...scene, actions: scene.actions.filter((_, i) => i !== index) };
}
