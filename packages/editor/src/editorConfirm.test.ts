import { describe, expect, it } from "vitest";
import { F_R, FRAME_STRIDE } from "./remote/protocol";
import { sceneEditor, settled, type testEditor } from "./testing/harness";
import { twoDiscsAndPoint } from "./testing/scenes";

/**
 * Every edit of a field says what it set and what Undo restores (doc/editConfirm.ts), as adds and
 * deletes say what they did: the values before are those at the edit's time once the edits asked
 * before it are applied, so two edits asked at once each name the value the other left.
 */
async function twoDiscs() {
  const h = await sceneEditor(twoDiscsAndPoint());
  h.editor.ui.setState({ t: 1 });
  return h;
}

const message = (h: ReturnType<typeof testEditor>) => h.editor.ui.getState().message;

describe("the message confirming an edit", () => {
  it("says the value set, the time and what Undo restores, for the table's fields and the canvas's gestures", async () => {
    const h = await twoDiscs();
    expect(await h.editor.updateBody("a", { r: 2 })).toBeNull();
    expect(message(h)).toEqual({
      text: 'Set disc "a" r = 2 at t = 1 s (Undo restores r = 1).',
      tone: "info",
    });
    expect(await h.editor.moveBody("b", 20, 3)).toBeNull();
    expect(message(h)?.text).toBe('Moved disc "b" to (20, 3) at t = 1 s (Undo moves it back to (10, 0)).');
    expect(await h.editor.giveVelocity("b", [1, -1])).toBeNull();
    expect(message(h)?.text).toBe(`Set disc "b"'s velocity to (1, -1) at t = 1 s (Undo restores (0, 0)).`);
    expect(await h.editor.strike("a", [0, 0], [-0.5, 0])).toBeNull();
    expect(message(h)?.text).toBe('Struck disc "a": velocity (2, 0) at t = 1 s (Undo restores (0, 0)).');
    expect(await h.editor.updatePoint("p1", [6, 5])).toBeNull();
    expect(message(h)?.text).toBe('Moved point "p1" to (6, 5) at t = 1 s (Undo moves it back to (5, 5)).');
    expect(await h.editor.setGlobal({ g: 1 })).toBeNull();
    expect(message(h)?.text).toBe("Set g = 1 at t = 1 s (Undo restores g = 9.81).");
    expect(await h.editor.rename("point", "p1", "pin")).toBeNull();
    expect(message(h)?.text).toBe('Renamed point "p1" to "pin" (Undo takes it back).');
    await settled(h.client);
  });

  it("names what Undo really restores: two edits asked at once, the second's old value is the first's new one", async () => {
    const h = await twoDiscs();
    const first = h.editor.updateBody("a", { r: 2 });
    const second = h.editor.updateBody("a", { r: 3 });
    expect(await first).toBeNull();
    expect(await second).toBeNull();
    expect(message(h)?.text).toBe('Set disc "a" r = 3 at t = 1 s (Undo restores r = 2).');
    await h.editor.undo();
    await settled(h.client);
    const f = await h.client.frame(1);
    expect(f.data[f.ids.indexOf("a") * FRAME_STRIDE + F_R], "Undo restored r = 2 indeed").toBe(2);
  });

  it("a refused edit keeps its refusal, with no confirmation", async () => {
    const h = await twoDiscs();
    const err = await h.editor.updateBody("a", { r: -1 });
    expect(err).toMatch(/a r: must be a positive/);
    expect(message(h)).toEqual({ text: err, tone: "error" });
  });
});
