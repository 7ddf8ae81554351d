// @vitest-environment jsdom
// Enter on the focused scene view adds the current tool's object at the centre of the view (the
// keyboard's way to add: tools 1-8 were keys, adding needed the pointer), selects it and says so; a
// centre already taken adds nothing and says what is in the way.
import { afterEach, describe, expect, it, vi } from "vitest";
import type { Action, SceneFile } from "../engineTypes";
import { bindKeyboard } from "../keyboard";
import { settled, testEditor } from "../testing/harness";
import { press } from "../testing/keys";
import { addAtCentre, NEW_LINE_PX } from "./addAtCentre";
import { NEW_DISC_PX, niceRadius } from "./gestures";

const scene: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [
    { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
    { time: 0, type: "addLine", id: "w", p1: [20, -5], p2: [20, 5], kind: "segment" },
    { time: 0, type: "addPoint", id: "q", p: [-20, 0] },
  ],
};

async function setup(view = { cx: 10, cy: 3, scale: 20 }) {
  const h = testEditor();
  expect(await h.editor.loadScene(scene, { undoable: false })).toBeNull();
  await settled(h.client);
  // the frame the canvas shows (it asks for one every animation frame)
  h.client.wantFrame(0);
  await vi.waitFor(() => expect(h.client.latestFrame?.ids).toEqual(["a"]));
  h.editor.ui.setState({ view });
  return h;
}

/** The actions the scene gained. */
const added = (doc: SceneFile): Action[] => doc.actions.slice(scene.actions.length);

afterEach(() => {
  document.body.replaceChildren();
});

describe("Enter: the tool's object at the centre of the view", () => {
  it("the Disc tool adds a disc of a click's size at the centre, selected, and says so", async () => {
    const { editor, client } = await setup();
    editor.ui.setState({ tool: "disc" });
    await addAtCentre(editor);
    await settled(client);
    const r = niceRadius(NEW_DISC_PX, 20);
    expect(added(editor.doc)).toMatchObject([{ type: "addBody", id: "b1", x: 10, y: 3, r }]);
    expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "b1" });
    expect(editor.ui.getState().message).toEqual({
      text: 'Added disc "b1" at the centre of the view (10, 3).',
      tone: "info",
    });
    expect(editor.history.getState().past).toHaveLength(1);
  });

  it("Line, Ray and Segment add a horizontal one of that kind across the centre; Point a point; each selected", async () => {
    const { editor, client } = await setup({ cx: -4, cy: 7, scale: 10 });
    const half = niceRadius(NEW_LINE_PX / 2, 10);
    for (const [tool, id] of [
      ["line", "l1"],
      ["ray", "l2"],
      ["segment", "l3"],
    ] as const) {
      editor.ui.setState({ tool });
      await addAtCentre(editor);
      await settled(client);
      expect(added(editor.doc).at(-1)).toEqual({
        time: 0,
        type: "addLine",
        id,
        p1: [-4 - half, 7],
        p2: [-4 + half, 7],
        kind: tool,
      });
      expect(editor.ui.getState().selection).toEqual({ kind: "line", id });
    }
    editor.ui.setState({ tool: "point" });
    await addAtCentre(editor);
    await settled(client);
    expect(added(editor.doc).at(-1)).toEqual({ time: 0, type: "addPoint", id: "p1", p: [-4, 7] });
    expect(editor.ui.getState().selection).toEqual({ kind: "point", id: "p1" });
    expect(editor.ui.getState().message?.text).toBe('Added point "p1" at the centre of the view (-4, 7).');
  });

  it("a centre panned to by the keys is rounded as a click there is: to the coarsest power of ten under a pixel", async () => {
    // at 20 px per unit a pixel is 0.05: positions to 0.01, as a click at the centre would give
    const { editor, client } = await setup({ cx: 10.123456789, cy: 3.98765, scale: 20 });
    editor.ui.setState({ tool: "disc" });
    await addAtCentre(editor);
    await settled(client);
    expect(added(editor.doc).at(-1)).toMatchObject({ type: "addBody", x: 10.12, y: 3.99 });
    expect(editor.ui.getState().message?.text).toBe(
      'Added disc "b1" at the centre of the view (10.12, 3.99).',
    );
    editor.ui.setState({ tool: "segment", view: { cx: 10.123456789, cy: -3.98765, scale: 20 } });
    await addAtCentre(editor);
    await settled(client);
    const half = niceRadius(NEW_LINE_PX / 2, 20);
    expect(half).toBe(5);
    expect(added(editor.doc).at(-1)).toMatchObject({
      type: "addLine",
      p1: [5.12, -3.99],
      p2: [15.12, -3.99],
    });
    // a centre clear of "a" (radius 1 at the origin) by less than the rounding: (0.70, 0.71) and
    // (0.71, 0.70) lie inside it, so the nearest round place clear of it
    editor.ui.setState({ tool: "point", view: { cx: 0.7049, cy: 0.7094, scale: 20 } });
    await addAtCentre(editor);
    await settled(client);
    expect(added(editor.doc).at(-1)).toMatchObject({ type: "addPoint", p: [0.71, 0.71] });
    expect(editor.ui.getState().message?.tone).toBe("info");
  });

  it("a centre already taken adds nothing and says what is in the way", async () => {
    const { editor, client } = await setup({ cx: 0.5, cy: 0, scale: 20 });
    for (const [tool, noun, button] of [
      ["disc", "disc", "Add body"],
      ["point", "point", "Add point"],
      ["segment", "segment", "Add line"],
    ] as const) {
      editor.ui.setState({ tool, selection: null, message: null });
      await addAtCentre(editor);
      await settled(client);
      expect(editor.ui.getState().message).toEqual({
        text: `Nothing added: a new ${noun} at the centre of the view would overlap body "a". Pan the view (arrow keys) to a free place, or use ${button}, which finds the nearest one.`,
        tone: "error",
      });
    }
    // a new disc keeps clear of lines and points too (a new line or point may cross them)
    editor.ui.setState({ tool: "disc", view: { cx: 20, cy: 0, scale: 20 } });
    await addAtCentre(editor);
    expect(editor.ui.getState().message?.text).toMatch(/would overlap line "w"/);
    editor.ui.setState({ view: { cx: -20, cy: 0.5, scale: 20 } });
    await addAtCentre(editor);
    expect(editor.ui.getState().message?.text).toMatch(/would overlap point "q"/);
    await settled(client);
    expect(added(editor.doc)).toEqual([]);
    expect(editor.history.getState().past).toHaveLength(0);
    expect(editor.ui.getState().selection).toBeNull();
    // before the canvas has a frame, the engine's refusal says it
    client.latestFrame = null;
    editor.ui.setState({ view: { cx: 0.5, cy: 0, scale: 20 } });
    await addAtCentre(editor);
    await settled(client);
    expect(editor.ui.getState().message).toEqual({
      text: 'a new disc here would overlap body "a" at time 0',
      tone: "error",
    });
    expect(added(editor.doc)).toEqual([]);
  });

  it("the tools that add nothing say which tools do", async () => {
    const { editor, client } = await setup();
    for (const [tool, label] of [
      ["move", "Move"],
      ["velocity", "Velocity"],
      ["cue", "Cue"],
    ] as const) {
      editor.ui.setState({ tool });
      await addAtCentre(editor);
      expect(editor.ui.getState().message).toEqual({
        text: `Enter adds at the centre of the view with Disc (4), Line (5), Ray (6), Segment (7), Point (8); the ${label} tool adds nothing.`,
        tone: "info",
      });
    }
    await settled(client);
    expect(added(editor.doc)).toEqual([]);
  });

  it("is Enter on the focused scene view, with the one-character shortcuts off too; Enter elsewhere adds nothing", async () => {
    const { editor, client } = await setup();
    const off = bindKeyboard(editor);
    editor.ui.setState({ tool: "point", characterKeys: false });
    const page = document.createElement("div");
    document.body.append(page);
    press(page, "Enter");
    await settled(client);
    expect(added(editor.doc)).toEqual([]);
    const c = document.createElement("canvas");
    c.tabIndex = 0;
    c.dataset.keys = "canvas";
    document.body.append(c);
    c.focus();
    expect(press(c, "Enter")).toBe(false);
    await settled(client);
    expect(added(editor.doc)).toEqual([{ time: 0, type: "addPoint", id: "p1", p: [10, 3] }]);
    off();
  });
});
