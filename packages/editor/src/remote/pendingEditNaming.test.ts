// beforeEdit: a later action the engine refuses during an edit's check is named by its index in the
// action list before the edit; a merged edit (host.ts mergeInto) leaves copies, not the same objects,
// and a merged action that changes nothing is dropped, so the later actions move up by one.
import { describe, expect, it } from "vitest";
import type { Action } from "../engineTypes";
import { beforeEdit, type PendingEdit } from "./pendingEdit";

const add = (id: string, x: number): Action => ({ time: 0, type: "addBody", id, x, y: 0, r: 1, m: 1 });
const kick: Action = { time: 5, type: "giveVelocity", id: "a", v: [1, 0] };
const mass: Action = { time: 2, type: "updateBody", id: "b", m: 2 };
const before: Action[] = [add("a", 0), add("b", 5), mass, kick, { ...kick }];
const pending = (undo: Action[]): PendingEdit => ({
  id: 1,
  undo: { actions: undo },
  checkTo: 5,
  horizon: 9,
  suffix: "",
});
const copies = (list: Action[]) => list.map((a) => JSON.parse(JSON.stringify(a)) as Action);

describe("beforeEdit", () => {
  it("names a copy by its index before the edit, the k-th copy of equal actions the k-th one", () => {
    // the merged action that changed nothing (mass) dropped: the two kicks at 2 and 3 were at 3 and 4
    const now = copies([add("a", 0), add("b", 5), kick, kick]);
    const info = { message: "actions[3]: would overlap", path: "actions[3].v" };
    expect(beforeEdit(info, pending(before), now)).toEqual({
      message: "actions[4]: would overlap",
      path: "actions[4].v",
    });
    expect(beforeEdit({ message: "actions[2]: x", path: "actions[2]" }, pending(before), now).path).toBe(
      "actions[3]",
    );
  });

  it("the same object is found by identity; an action the list before lacks keeps the engine's index", () => {
    const now = [before[0] as Action, before[1] as Action, kick];
    expect(beforeEdit({ message: "actions[2]: x", path: "actions[2]" }, pending(before), now).path).toBe(
      "actions[3]",
    );
    const fresh: Action = { time: 2, type: "updateBody", id: "b", m: 3 };
    const info = { message: "actions[2]: x", path: "actions[2]" };
    expect(beforeEdit(info, pending(before), [add("a", 0), add("b", 5), fresh])).toEqual(info);
  });
});
