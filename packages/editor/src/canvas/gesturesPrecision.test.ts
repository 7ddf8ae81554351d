// What the pointer tools write into the scene is at the pointer's precision (pointerPlace.ts): at
// 10 px per unit a click, a drop, a drawn velocity or a strike gives one decimal, not the digits of
// the pointer's position; and a drop next to a disc is never rounded into a refusal.
import { describe, expect, it } from "vitest";
import { NO_STRIKE_DIRECTION } from "../editor";
import type { SceneFile } from "../engineTypes";
import { F_X, type Frame } from "../remote/protocol";
import { settled, testEditor } from "../testing/harness";
import { CanvasGestures, NEW_DISC_PX, niceRadius } from "./gestures";

const SCENE: SceneFile = {
  format: "chapgame",
  version: 1,
  g: 0,
  gravity: [0, 0],
  actions: [{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] }],
};
/** The view is centred on the disc at 10 px per unit: screen (400 + 10 x, 300 − 10 y). */
const size = { width: 800, height: 600 };
const CENTRE: [number, number] = [400, 300];
/** A new disc's radius at 10 px per unit. */
const NEW_R = niceRadius(NEW_DISC_PX, 10);

async function setup() {
  const h = testEditor();
  expect(await h.editor.loadScene(SCENE, { undoable: false })).toBeNull();
  await settled(h.client);
  const frame: Frame = await h.client.frame(0);
  h.editor.ui.setState({ view: { cx: 0, cy: 0, scale: 10 } });
  const g = new CanvasGestures(h.editor, {
    frame: () => frame,
    size: () => size,
    viewMoved() {},
    redraw() {},
  });
  return { ...h, g };
}

function drag(g: CanvasGestures, from: [number, number], to: [number, number]) {
  g.down(from, false);
  g.move(to);
  g.up(to);
}

describe("the pointer's precision", () => {
  it("a clicked disc or point, a drawn segment: one decimal at 10 px per unit, written short", async () => {
    const { editor, client, g } = await setup();
    editor.ui.setState({ tool: "disc" });
    drag(g, [433.37, 287.71], [433.37, 287.71]); // (3.337, 1.229)
    await settled(client);
    editor.ui.setState({ tool: "point" });
    drag(g, [100.123, 100.456], [100.123, 100.456]); // (−29.9877, 19.9544)
    await settled(client);
    editor.ui.setState({ tool: "segment" });
    drag(g, [150.55, 520.04], [350.77, 520.04]); // level at y = −22.004
    await settled(client);
    // each accepted and said, the last one showing (with the short decimals)
    expect(editor.ui.getState().message).toEqual({
      text: 'Added segment "l1" from (-24.9, -22) to (-4.9, -22).',
      tone: "info",
    });
    expect(editor.doc.actions.slice(1)).toMatchObject([
      { type: "addBody", x: 3.3, y: 1.2, r: NEW_R },
      { type: "addPoint", p: [-30, 20] },
      { type: "addLine", p1: [-24.9, -22], p2: [-4.9, -22], kind: "segment" },
    ]);
    // the scene file holds the short decimals
    expect(JSON.stringify(editor.doc.actions.slice(1))).not.toMatch(/\d\.\d{2,}/);
  });

  it("a dragged disc lands rounded; a drawn velocity and a cue strike are rounded to what a pixel changes", async () => {
    const { editor, client, g } = await setup();
    drag(g, CENTRE, [456.789, 312.345]); // (5.6789, −1.2345)
    await settled(client);
    // (each edit at the instant the disc was added changes its addBody: doc/mergeEdit.ts)
    expect(editor.doc.actions).toMatchObject([{ type: "addBody", id: "a", x: 5.7, y: -1.2 }]);
    // the frame shown is still t = 0's: the disc is picked up at the centre
    editor.ui.setState({ tool: "velocity" });
    drag(g, CENTRE, [412.34, 243.22]); // an arrow (1.234, 5.678) of half a second: a pixel is 0.2
    await settled(client);
    expect(editor.doc.actions).toMatchObject([{ type: "addBody", id: "a", v: [2.5, 11.4] }]);
    editor.ui.setState({ tool: "cue" });
    drag(g, [403.37, 302.13], [403.37, 302.13]); // 4 per unit of offset (−0.337, 0.213): a pixel is 0.4
    await settled(client);
    expect(editor.doc.actions).toMatchObject([{ type: "addBody", id: "a", v: [-1.3, 0.9] }]);
  });

  it("a cue click within a pixel of the centre still strikes (the smallest velocity at that precision); at the centre it is refused", async () => {
    const { editor, client, g } = await setup();
    editor.ui.setState({ tool: "cue" });
    // 4 per unit of offset (−0.01, −0.004): (−0.04, −0.016), which rounds to [0, 0] at a step of 0.1
    drag(g, [400.1, 300.04], [400.1, 300.04]);
    await settled(client);
    // struck, and said (not refused)
    expect(editor.ui.getState().message).toEqual({
      text: 'Struck disc "a": velocity (-0.1, 0) at t = 0 s (Undo restores (0, 0)).',
      tone: "info",
    });
    expect(editor.doc.actions).toMatchObject([{ type: "addBody", id: "a", v: [-0.1, 0] }]);
    // the disc moves off to the left: struck, not stopped
    expect((await client.frame(1)).data[F_X]).toBeLessThan(0);
    const before = editor.doc;
    drag(g, CENTRE, CENTRE); // the centre itself: no direction
    await settled(client);
    expect(editor.ui.getState().message).toEqual({ text: NO_STRIKE_DIRECTION, tone: "error" });
    expect(editor.doc).toEqual(before);
  });

  it("a disc clicked beside another is never rounded into it: the nearest round place clear of it, accepted", async () => {
    const { editor, client, g } = await setup();
    const r = NEW_R;
    expect(r).toBe(1.8); // touching "a" at 2.8
    // rounded to one decimal the new disc would overlap "a": the engine refuses that place
    expect(await editor.addBody(2, 1.9, r)).toMatch(/overlap/);
    expect(editor.doc.actions).toHaveLength(1);
    editor.ui.setState({ tool: "disc" });
    drag(g, [420.4, 280.8], [420.4, 280.8]); // (2.04, 1.92): 2.8014 from "a", clear of it
    await settled(client);
    expect(editor.ui.getState().message).toEqual({
      text: 'Added disc "b1" at (2.1, 1.9), radius 1.8.',
      tone: "info",
    });
    expect(editor.doc.actions.at(-1)).toMatchObject({ type: "addBody", x: 2.1, y: 1.9, r });
  });
});
