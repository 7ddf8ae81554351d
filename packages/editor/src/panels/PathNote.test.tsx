// @vitest-environment jsdom
import { act, cleanup, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { cradleEditor } from "../testing/harness";
import { PathNote } from "./PathNote";

afterEach(cleanup);

async function setup() {
  const h = await cradleEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <PathNote />
    </EditorContext.Provider>,
  );
  return h;
}

/** The id of a body of the scene (Newton's cradle). */
function firstBody(editor: Awaited<ReturnType<typeof cradleEditor>>["editor"]): string {
  const add = editor.doc.actions.find((a) => a.type === "addBody");
  if (add?.type !== "addBody") throw new Error("the cradle scene has no body");
  return add.id;
}

/** The note's live region (always there) and what it says. */
const region = () => screen.getByRole("status");

describe("the Path view's note", () => {
  it("says to select a body while Path is on and no body is selected, and nothing otherwise", async () => {
    const { editor } = await setup();
    const id = firstBody(editor);
    expect(region().textContent).toBe("");
    act(() => editor.ui.setState({ path: true, selection: null }));
    expect(region().textContent).toBe("select a body");
    act(() => editor.ui.setState({ selection: { kind: "line", id: "floor" } }));
    expect(region().textContent).toBe("select a body");
    act(() => editor.ui.setState({ selection: { kind: "body", id }, pathShown: { id, cutAt: null } }));
    expect(region().textContent).toBe("");
    act(() => editor.ui.setState({ path: false, selection: null }));
    expect(region().textContent).toBe("");
  });

  it("says where a path too long to draw whole was cut, while Path is on", async () => {
    const { editor } = await setup();
    const id = firstBody(editor);
    act(() =>
      editor.ui.setState({ path: true, selection: { kind: "body", id }, pathShown: { id, cutAt: 12.5 } }),
    );
    expect(region().textContent).toBe("drawn up to t = 12.5 s (too long to draw whole)");
    act(() => editor.ui.setState({ path: false }));
    expect(region().textContent).toBe("");
  });
});
