// @vitest-environment jsdom
// The Add body / Add line / Add point buttons put the new object near the centre of the view where
// it touches nothing (they once always used the exact centre, so in any scene with something there
// every Add was refused with an overlap message), and select it (each of the three) only once it
// exists.
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
    await click("Add body");
    await waitFor(() => expect(editor.doc.actions.some((a) => "id" in a && a.id === "b1")).toBe(true));
    await waitFor(() => expect(editor.ui.getState().selection).toEqual({ kind: "body", id: "b1" }));
    await click("Add point");
    await waitFor(() => expect(editor.doc.actions.some((a) => a.type === "addPoint")).toBe(true));
    await waitFor(() => expect(editor.ui.getState().selection).toEqual({ kind: "point", id: "p1" }));
    await click("Add line");
    await waitFor(() => expect(editor.doc.actions.some((a) => a.type === "addLine")).toBe(true));
    await waitFor(() => expect(editor.ui.getState().selection).toEqual({ kind: "line", id: "l1" }));
    expect(editor.ui.getState().message).toBeNull();
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
