// @vitest-environment jsdom
/**
 * An EditableCell records its draft in the editor's OpenDrafts while the text typed differs from
 * the value shown and no commit of it is in flight, and clears it when it closes or unmounts: what
 * a delete, a rename or a load reads to say which drafts it dropped (openDrafts.ts).
 */
import { act, cleanup, fireEvent, render } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { openCell } from "../testing/editableCell";
import { testEditor } from "../testing/harness";
import { EditableCell } from "./EditableCell";

afterEach(cleanup);

const owner = { kind: "body" as const, id: "b3", field: "r" };

describe("useOpenDraft, through EditableCell", () => {
  it("records the text typed while it differs from the value, and clears it on Escape", () => {
    const { editor } = testEditor();
    render(
      <EditorContext.Provider value={editor}>
        <EditableCell label="b3 r" value="1" onCommit={async () => null} owner={owner} />
      </EditorContext.Provider>,
    );
    const input = openCell("b3 r");
    expect(editor.drafts.all(), "opened, nothing typed").toEqual([]);
    fireEvent.change(input, { target: { value: "-1" } });
    expect(editor.drafts.all()).toEqual([{ label: "b3 r", text: "-1", owner }]);
    fireEvent.change(input, { target: { value: "1" } });
    expect(editor.drafts.all(), "the value shown typed again").toEqual([]);
    fireEvent.change(input, { target: { value: "abc" } });
    fireEvent.keyDown(input, { key: "Escape" });
    expect(editor.drafts.all()).toEqual([]);
  });

  it("keeps a refused draft, drops one while its commit is in flight, and clears it when the cell unmounts", async () => {
    const { editor } = testEditor();
    let answer: (err: string | null) => void = () => {};
    const view = render(
      <EditorContext.Provider value={editor}>
        <EditableCell
          label="b3 r"
          value="1"
          onCommit={() => new Promise((r) => (answer = r))}
          owner={owner}
        />
      </EditorContext.Provider>,
    );
    const input = openCell("b3 r");
    fireEvent.change(input, { target: { value: "-1" } });
    fireEvent.keyDown(input, { key: "Enter" });
    expect(editor.drafts.all(), "being applied: not a draft an edit would drop").toEqual([]);
    await act(async () => answer("b3 r: must be a positive finite number (got -1)"));
    expect(editor.drafts.all()).toEqual([{ label: "b3 r", text: "-1", owner }]);
    view.unmount();
    expect(editor.drafts.all()).toEqual([]);
  });
});
