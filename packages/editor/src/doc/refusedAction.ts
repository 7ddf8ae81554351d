/**
 * The scene's refused action: the one the engine refused when the computation reached it (the
 * scene's first action fine, a later one not: a disc added at t = 1 where another disc is then),
 * which stopped the computation there. It never happened, so no table row and no Event log entry
 * shows it; refusedAction finds it from the info's stop (its path `actions[i]` and the scene the
 * index refers to), and actionFields / withActionChanged let the author change its fields (the
 * cell names the tables use: x, vx, x1…, and t for its time). Pure.
 */
import type { Action, SceneFile } from "../engineTypes";
import { inApplyingOrder } from "../remote/actionIndices";
import { actionIndexOf, actionName } from "./actionRefs";
import { type ActionEntry, withoutAction } from "./removeAction";

export interface RefusedAction {
  /** Its index in the scene's actions (the engine's `actions[i]`). */
  index: number;
  action: Action;
  /** The engine's path of the refusal (`actions[1]`, `actions[1].x`). */
  path: string;
  /** The engine's reason, its path taken off ("body "b3" would overlap body "a" at time 1"). */
  reason: string;
  /** How the author knows it ("the action at t = 1 s that adds disc "b3""). */
  name: string;
}

/** The refused action of a stopped computation, or null (not stopped, or stopped by no action). */
export function refusedAction(info: {
  stopped: string | null;
  stoppedPath: string | null;
  doc: SceneFile | null;
}): RefusedAction | null {
  const { stopped, stoppedPath: path, doc } = info;
  const index = actionIndexOf(path);
  const action = index === null ? undefined : doc?.actions[index];
  if (stopped === null || path === null || index === null || action === undefined) return null;
  const head = `${path}: `;
  const reason = stopped.startsWith(head) ? stopped.slice(head.length) : stopped;
  return { index, action, path, reason, name: actionName(action) ?? path };
}

/** The entry an action is checked against before it is changed or removed (removeAction.ts). */
export function entryOf(a: Action): ActionEntry {
  return { time: a.time, type: a.type, id: "id" in a ? a.id : null };
}

/** One editable number of an action: its cell's name and value, and the action with it set. */
export interface ActionField {
  name: string;
  value: number;
  set(v: number): Action;
}

/** The names the tables give a vector's components. */
const COMPONENTS: Record<string, [string, string]> = {
  v: ["vx", "vy"],
  p: ["x", "y"],
  p1: ["x1", "y1"],
  p2: ["x2", "y2"],
  gravity: ["gravity x", "gravity y"],
};

/** The fields of `a` the author can change: its time ("t"), then each number it holds, a vector's two components apart. */
export function actionFields(a: Action): ActionField[] {
  const fields: ActionField[] = [{ name: "t", value: a.time, set: (v) => ({ ...a, time: v }) }];
  for (const [key, value] of Object.entries(a)) {
    if (key === "time") continue;
    if (typeof value === "number") {
      fields.push({ name: key === "mu" ? "μ" : key, value, set: (v) => ({ ...a, [key]: v }) as Action });
      continue;
    }
    const names = COMPONENTS[key];
    if (names === undefined || !Array.isArray(value) || value.length !== 2) continue;
    for (const axis of [0, 1] as const) {
      const set = (v: number): Action => {
        const next: [number, number] = [value[0], value[1]];
        next[axis] = v;
        return { ...a, [key]: next } as Action;
      };
      fields.push({ name: names[axis], value: value[axis] as number, set });
    }
  }
  return fields;
}

/**
 * The scene with `actions[index]` replaced by `next`, kept in applying order (a changed time moves
 * it among the others: the engine's indices then name the actions of this list); throws a message
 * unless that action is `entry`'s.
 */
export function withActionChanged(
  scene: SceneFile,
  index: number,
  entry: ActionEntry,
  next: Action,
): SceneFile {
  const rest = withoutAction(scene, index, entry).actions;
  return inApplyingOrder({ ...scene, actions: [...rest.slice(0, index), next, ...rest.slice(index)] });
}
