import { describe, expect, it } from "vitest";
import type { SceneFile } from "../engineTypes";
import type { Frame } from "../remote/protocol";
import { settled, testEditor } from "../testing/harness";
import { CanvasGestures } from "./gestures";

const SCENE: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 0,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] }],
};
const size = { width: 800, height: 600 };
/** The disc's centre on screen: the view is centred on it at 10 px per unit. */
const CENTRE: [number, number] = [400, 300];

async function setup() {
  const h = testEditor();
  expect(await h.editor.loadScene(SCENE, { undoable: false })).toBeNull();
  await settled(h.client);
  const frame: Frame = await h.client.frame(0);
  h.editor.ui.setState({ view: { cx: 0, cy: 0, scale: 10 } });
  let redraws = 0;
  const g = new CanvasGestures(h.editor, {
    frame: () => frame,
    size: () => size,
    viewMoved: () => {},
    redraw: () => {
      redraws++;
    },
  });
  return { ...h, g, redraws: () => redraws };
}

/** Presses at `from`, drags through `to` and returns before releasing. */
function drag(g: CanvasGestures, from: [number, number], to: [number, number], shift = false) {
  g.down(from, shift);
  g.move([(from[0] + to[0]) / 2, (from[1] + to[1]) / 2]);
  g.move(to);
}

describe("canvas gestures", () => {
  it("a Disc or Point click on an object adds nothing, selects it and says so", async () => {
    const { editor, client, g } = await setup();
    for (const tool of ["disc", "point"] as const) {
      editor.ui.setState({ tool, selection: null, message: null });
      g.down(CENTRE, false);
      g.up(CENTRE);
      await settled(client);
      expect(editor.doc.actions).toHaveLength(1);
      expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "a" });
      expect(editor.ui.getState().message).toEqual({
        text: `Nothing added: body "a" is there (selected now). The ${tool === "disc" ? "Disc" : "Point"} tool adds where the click meets nothing.`,
        tone: "info",
      });
    }
  });

  it("a disc dragged and released moves there in one undo step (the control case)", async () => {
    const { editor, client, g } = await setup();
    drag(g, CENTRE, [450, 300]);
    expect(g.overlay).toEqual({ kind: "disc", x: 5, y: 0, r: 1 });
    g.up([450, 300]);
    await settled(client);
    // moved at the instant it was added: its addBody (doc/mergeEdit.ts)
    expect(editor.doc.actions).toMatchObject([{ type: "addBody", id: "a", x: 5, y: 0 }]);
    expect(editor.history.getState().past.length).toBe(1);
  });

  it("a disc dragged (move, then velocity) is selected, as a click selects it (Delete removed the one selected before)", async () => {
    const { editor, client, g } = await setup();
    const other = { kind: "line", id: "wall" } as const;
    editor.ui.setState({ selection: other, highlight: ["line:wall"] });
    drag(g, CENTRE, [450, 300]);
    g.up([450, 300]);
    expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "a" });
    expect(editor.ui.getState().highlight).toEqual([]);
    await settled(client);
    editor.ui.setState({ selection: other, tool: "velocity" });
    // (the host's frame is the one at t = 0: the disc is still drawn at the centre)
    drag(g, CENTRE, [400, 250]);
    g.up([400, 250]);
    expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "a" });
    await settled(client);
    expect(editor.doc.actions).toMatchObject([{ type: "addBody", id: "a", x: 5, v: [0, 10] }]);
    // a drag cancelled selects nothing
    editor.ui.setState({ selection: other, tool: "move" });
    drag(g, CENTRE, [500, 300]);
    g.cancel();
    expect(editor.ui.getState().selection).toEqual(other);
  });

  it("every object a pointer adds is selected: a clicked disc or point, a dragged line, ray or segment", async () => {
    const { editor, client, g } = await setup();
    const other = { kind: "body", id: "a" } as const;
    const adds = [
      { tool: "disc", from: [100, 100], to: [100, 100], selection: { kind: "body", id: "b1" } },
      { tool: "point", from: [700, 100], to: [700, 100], selection: { kind: "point", id: "p1" } },
      { tool: "line", from: [100, 500], to: [300, 500], selection: { kind: "line", id: "l1" } },
      { tool: "ray", from: [500, 500], to: [700, 450], selection: { kind: "line", id: "l2" } },
      { tool: "segment", from: [100, 550], to: [300, 560], selection: { kind: "line", id: "l3" } },
    ] as const;
    for (const add of adds) {
      editor.ui.setState({ tool: add.tool, selection: other });
      if (add.from === add.to) g.down([...add.from], false);
      else drag(g, [...add.from], [...add.to]);
      g.up([...add.to]);
      await settled(client);
      // accepted, and said (an add once said nothing): which object, where
      const noun =
        add.tool === "disc"
          ? "disc"
          : add.tool === "line" || add.tool === "ray" || add.tool === "segment"
            ? add.tool
            : "point";
      expect(editor.ui.getState().message).toEqual({
        text: expect.stringMatching(new RegExp(`^Added ${noun} "${add.selection.id}" (at|from) \\(`)),
        tone: "info",
      });
      expect(editor.ui.getState().selection, add.tool).toEqual(add.selection);
    }
    expect(editor.doc.actions.map((a) => a.type)).toEqual([
      "addBody",
      "addBody",
      "addPoint",
      "addLine",
      "addLine",
      "addLine",
    ]);
  });

  it("a pointer add the engine refuses selects nothing new (a line through the disc)", async () => {
    const { editor, client, g } = await setup();
    const other = { kind: "body", id: "a" } as const;
    editor.ui.setState({ tool: "segment", selection: other });
    drag(g, [300, 300], [500, 300]);
    g.up([500, 300]);
    await settled(client);
    expect(editor.ui.getState().message?.tone).toBe("error");
    expect(editor.ui.getState().selection).toEqual(other);
  });

  it("Escape during a move drag restores the scene: no action, no undo step, the release applies nothing", async () => {
    const { editor, client, g, redraws } = await setup();
    const before = editor.doc;
    drag(g, CENTRE, [450, 300]);
    const drawn = redraws();
    expect(g.cancel()).toBe(true);
    expect(g.overlay).toBeNull();
    expect(g.active).toBe(false);
    expect(redraws()).toBeGreaterThan(drawn); // the preview disappears
    g.move([500, 300]);
    g.up([500, 300]);
    await settled(client);
    expect(editor.doc).toBe(before);
    expect(editor.history.getState().past.length).toBe(0);
    expect(g.cancel()).toBe(false); // nothing left to cancel
  });

  it("Escape during a velocity drag of a playing scene gives no velocity and lets playback go on", async () => {
    const { editor, client, g } = await setup();
    const before = editor.doc;
    editor.ui.setState({ tool: "velocity", playing: true });
    drag(g, CENTRE, [400, 250]);
    expect(editor.ui.getState().playing).toBe(false); // picked up: paused
    expect(g.overlay).toEqual({ kind: "arrow", from: [0, 0], to: [0, 5] });
    g.cancel();
    expect(editor.ui.getState().playing).toBe(true);
    g.up([400, 250]);
    await settled(client);
    expect(editor.doc).toBe(before);
    expect(editor.history.getState().past.length).toBe(0);
  });

  it("Escape during a Shift+drag velocity handle of a paused scene keeps it paused", async () => {
    const { editor, client, g } = await setup();
    drag(g, CENTRE, [420, 280], true);
    expect(g.overlay?.kind).toBe("arrow");
    g.cancel();
    g.up([420, 280]);
    await settled(client);
    expect(editor.ui.getState().playing).toBe(false);
    expect(editor.history.getState().past.length).toBe(0);
  });

  it("Escape while drawing a line (its second end) adds no line", async () => {
    const { editor, client, g } = await setup();
    const before = editor.doc;
    editor.ui.setState({ tool: "segment" });
    drag(g, [100, 100], [200, 150]);
    expect(g.overlay).toMatchObject({ kind: "line", lineKind: "segment" });
    g.cancel();
    g.up([200, 150]);
    await settled(client);
    expect(editor.doc).toBe(before);
  });

  it("Escape during a pan puts the view back; a release without a drag is a click", async () => {
    const { editor, g } = await setup();
    editor.ui.setState({ selection: { kind: "body", id: "a" } });
    const view = editor.ui.getState().view;
    drag(g, [100, 100], [160, 130]);
    expect(editor.ui.getState().view).not.toEqual(view);
    g.cancel();
    expect(editor.ui.getState().view).toBe(view);
    g.up([160, 130]);
    // the release is no click (a click on empty space would clear the selection)
    expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "a" });
    g.down([100, 100], false);
    g.up([101, 100]);
    expect(editor.ui.getState().selection).toBeNull();
  });
});
