// After an edit the session computes ahead (EditorCompute.ensureAhead): the horizon ends at the
// later of the old horizon (brought back after the edit) and the current time plus the Calculation
// panel's seconds. It used to grow by those seconds with every edit (audit s18, s07): the compute
// request counted them from the old horizon, brought back by then.
import { newtonsCradle } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { settled, testEditor } from "./testing/harness";

async function cradle(options: { slow?: boolean } = {}) {
  const h = testEditor(options);
  expect(await h.editor.loadScene(newtonsCradle(), { undoable: false })).toBeNull();
  await settled(h.client);
  return h;
}

const massOf = (m: number, t: number) => [{ time: t, type: "updateBody" as const, id: "c1", m }];

describe("computing ahead after an edit", () => {
  it("edits at t = 0 keep the horizon at 10 s ahead, not 10 s more per edit", async () => {
    const h = await cradle();
    expect(h.client.getSnapshot().horizon).toBe(10);
    for (let i = 0; i < 4; i++) {
      expect(await h.editor.edit(massOf(2 + i, 0))).toBeNull();
      await settled(h.client);
      expect(h.client.getSnapshot().horizon).toBe(10);
    }
  });

  it("an edit at t = 5 with the horizon at 30 keeps 30; at t = 25 it reaches 35", async () => {
    const h = await cradle();
    await h.editor.goTo(30);
    await settled(h.client);
    expect(h.client.getSnapshot().horizon).toBe(30);
    h.editor.ui.setState({ t: 5 });
    expect(await h.editor.edit(massOf(2, 5))).toBeNull();
    await settled(h.client);
    expect(h.client.getSnapshot().horizon).toBe(30);
    h.editor.ui.setState({ t: 25 });
    expect(await h.editor.edit(massOf(3, 25))).toBeNull();
    await settled(h.client);
    expect(h.client.getSnapshot().horizon).toBe(35);
  });

  it("the same with a slow host (the edit's check and the old history's return take many rounds)", async () => {
    const h = await cradle({ slow: true });
    for (let i = 0; i < 2; i++) {
      expect(await h.editor.edit(massOf(2 + i, 0))).toBeNull();
      await settled(h.client);
      expect(h.client.getSnapshot().horizon).toBe(10);
    }
  });
});
