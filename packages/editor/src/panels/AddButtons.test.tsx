// @vitest-environment jsdom
// The Add body / Add line / Add point buttons put the new object near the centre of the view where
// it touches nothing (they once always used the exact centre, so in any scene with something there
// every Add was refused with an overlap message), and select it (each of the three) only once it
// exists. Each says what it added and where, or why it added nothing (they once said nothing).
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { BodiesTable } from "./BodiesTable";
import { LinesTable } from "./LinesTable";
import { PointsTable } from "./PointsTable";

afterEach(cleanup);

async function setup() {
  const h = testEditor();
  await h.editor.loadScene(newtonsCradle(), { undoable: false });
  await settled(h.client);
  // the view is centred on c1 (a disc of radius 1 at the origin)
  h.editor.ui.setState({ view: { cx: 0, cy: 0, scale: 20 } });
  render(
    <EditorContext.Provider value={h.editor}>
      <BodiesTable />
      <LinesTable />
      <PointsTable />
    </EditorContext.Provider>,
  );
  await waitFor(() => expect(h.client.latestFrame?.ids.length).toBe(6));
  return h;
}

async function click(name: string) {
  await act(async () => {
    fireEvent.click(screen.getByRole("button", { name }));
  });
}

describe("Add buttons", () => {
  it("Add body, Add point and Add line succeed with a disc at the centre of the view, each selecting what it added", async () => {
    // (Add point and Add line once left the selection on the body added before them, while Add
    // body, a click and Enter selected what they added.)
    const { editor } = await setup();
    const said = () => editor.ui.getState().message;
    await click("Add body");
    await waitFor(() => expect(editor.doc.actions.some((a) => "id" in a && a.id === "b1")).toBe(true));
    await waitFor(() => expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "b1" }));
    const b1 = editor.doc.actions.find((a) => a.type === "addBody" && a.id === "b1");
    expect(said()).toEqual({
      text: `Added disc "b1" at (${b1?.type === "addBody" ? `${b1.x}, ${b1.y}` : ""}), radius 1.`,
      tone: "info",
    });
    await click("Add point");
    await waitFor(() => expect(editor.doc.actions.some((a) => a.type === "addPoint")).toBe(true));
    await waitFor(() => expect(editor.ui.getState().selection).toEqual({ kind: "point", id: "p1" }));
    const p1 = editor.doc.actions.find((a) => a.type === "addPoint");
    expect(said()).toEqual({
      text: `Added point "p1" at (${p1?.type === "addPoint" ? p1.p.join(", ") : ""}).`,
      tone: "info",
    });
    await click("Add line");
    await waitFor(() => expect(editor.doc.actions.some((a) => a.type === "addLine")).toBe(true));
    await waitFor(() => expect(editor.ui.getState().selection).toEqual({ kind: "line", id: "l1" }));
    const l1 = editor.doc.actions.find((a) => a.type === "addLine");
    expect(said()).toEqual({
      text: `Added segment "l1" from (${l1?.type === "addLine" ? `${l1.p1.join(", ")}) to (${l1.p2.join(", ")}` : ""}).`,
      tone: "info",
    });
    // moved off c1 on a ring around the centre, each is still at the pointer's precision (a pixel
    // at 20 px per unit is 0.05: two decimals), not at the digits of a cosine
    const added = editor.doc.actions.filter((a) => "id" in a && ["b1", "p1", "l1"].includes(a.id));
    const numbers = added.flatMap((a) => JSON.stringify(a).match(/-?\d+(\.\d+)?(e-?\d+)?/g) ?? []);
    expect(numbers.filter((n) => /\.\d{3,}|e-/.test(n))).toEqual([]);
    expect(added).toHaveLength(3);
  });

  it("a refused Add body selects nothing", async () => {
    const { editor } = await setup();
    act(() => editor.ui.setState({ selection: null }));
    await act(async () => {
      expect(await editor.addBody(0, 0, 1)).toMatch(/overlap/);
    });
    expect(editor.ui.getState().selection).toBeNull();
  });
});

describe("Add buttons: refusals and times", () => {
  it("with no free place near the centre, nothing is added and the message says why, what is there and what to do", async () => {
    const { editor, client } = await setup();
    // the view inside a disc far larger than the place searched (100 units around the centre)
    const big = { time: 0, type: "addBody", id: "big", x: 0, y: 0, r: 1e6, m: 1 } as const;
    await act(async () => {
      await editor.loadScene(
        { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions: [big] },
        { fit: false },
      );
    });
    await settled(client);
    await waitFor(() => expect(client.latestFrame?.ids).toEqual(["big"]));
    act(() => editor.ui.setState({ view: { cx: 0, cy: 0, scale: 20 }, selection: null, message: null }));
    const before = editor.doc;
    await click("Add body");
    await waitFor(() => expect(editor.ui.getState().message).not.toBeNull());
    expect(editor.ui.getState().message).toEqual({
      text: 'Add body: nothing added: no free place for a new disc of radius 1 within 100 of the centre of the view (0, 0) (body "big" is there). Zoom out or pan to an emptier part of the scene, then press Add body again.',
      tone: "error",
    });
    expect(editor.doc).toBe(before);
    expect(editor.ui.getState().selection).toBeNull();
  });

  it("a place the engine refuses names the field of the new object", async () => {
    const { editor } = await setup();
    act(() => editor.ui.setState({ view: { cx: 2e30, cy: 0, scale: 20 } }));
    await click("Add point");
    await waitFor(() => expect(editor.ui.getState().message).not.toBeNull());
    expect(editor.ui.getState().message).toEqual({
      text: expect.stringMatching(/^new point x: must be at most 1e\+30 in size/),
      tone: "error",
    });
    expect(editor.doc.actions.some((a) => a.type === "addPoint")).toBe(false);
  });

  it("an object added after the start says at which time", async () => {
    const { editor } = await setup();
    await act(async () => {
      await editor.goTo(0.5);
    });
    act(() => editor.ui.setState({ view: { cx: 0, cy: 100, scale: 20 } }));
    await click("Add point");
    await waitFor(() =>
      expect(editor.ui.getState().message).toEqual({
        text: 'Added point "p1" at (0, 100), at t = 0.5 s.',
        tone: "info",
      }),
    );
  });
});
