// @vitest-environment jsdom
// The Event log while the worker computes: progress reports arrive more often than a log page can
// be read and answered, and the log must still follow the scene (it once showed the previous
// scene's events for the whole of a long computation: every report discarded the pending page).
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import type { Editor } from "../editor";
import type { RequestMessage } from "../remote/protocol";
import { settled, testEditor } from "../testing/harness";
import { EventLog, kindLabel } from "./EventLog";

afterEach(cleanup);

/** Milliseconds between simulated progress reports, and the delay of every event-page reply. */
const REPORT_MS = 15;
const REPLY_MS = 40;

/** The Event log of `editor`, rendered; its table. */
function renderLog(editor: Editor): HTMLElement {
  render(
    <EditorContext.Provider value={editor}>
      <EventLog />
    </EditorContext.Provider>,
  );
  return screen.getByRole("table", { name: "Event log" });
}

describe("EventLog", () => {
  it("follows a newly loaded scene while progress reports keep arriving faster than pages", async () => {
    const h = testEditor();
    await h.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(h.client);
    const log = renderLog(h.editor);
    await waitFor(() => expect(within(log).getAllByText("striker").length).toBeGreaterThan(0));

    // Every event page is answered later than the next progress report (a busy worker).
    const handle = h.host.handle.bind(h.host);
    h.host.handle = (m: RequestMessage) => {
      if (m.op === "events") setTimeout(() => handle(m), REPLY_MS);
      else handle(m);
    };
    const host = h.host as unknown as { changed(docChanged: boolean): void };
    const reports = setInterval(() => host.changed(false), REPORT_MS);
    try {
      await act(async () => {
        await h.editor.loadScene(
          {
            format: "chapgame",
            version: 1,
            g: 9.81,
            gravity: [0, 0],
            actions: [{ time: 0, type: "addBody", id: "lonely", x: 0, y: 0, r: 1, m: 1 }],
          },
          { undoable: false },
        );
      });
      await waitFor(() => expect(within(log).getAllByText("lonely").length).toBe(1), { timeout: 3000 });
      expect(within(log).queryAllByText("striker")).toEqual([]);
    } finally {
      clearInterval(reports);
    }
  });

  it("says what each action entry did, and only the kind for collisions and stops", async () => {
    const h = testEditor();
    await h.editor.loadScene(
      {
        format: "chapgame",
        version: 1,
        g: 9.81,
        gravity: [0, 0],
        actions: [
          { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0.5 },
          { time: 0, type: "addLine", id: "w", p1: [10, -5], p2: [10, 5], kind: "segment" },
          { time: 0.25, type: "giveVelocity", id: "a", v: [4, 0] },
        ],
      },
      { undoable: false },
    );
    await settled(h.client);
    const log = renderLog(h.editor);
    await waitFor(() => expect(within(log).getAllByText("action: add body")).toHaveLength(1));
    expect(within(log).getAllByText("action: add line")).toHaveLength(1);
    expect(within(log).getAllByText("action: give velocity")).toHaveLength(1);
    expect(within(log).getAllByText("stop")).toHaveLength(1);
  });

  it("labels an entry by its kind, with the action's type in words for an action", () => {
    const base = { time: 1, ids: ["a"], point: null, normal: null, impulse: null };
    expect(kindLabel({ ...base, type: "bodyLine" })).toBe("body–line");
    expect(kindLabel({ ...base, type: "action", action: "setGlobal" })).toBe("action: set global");
    expect(kindLabel({ ...base, type: "action", action: "removePoint" })).toBe("action: remove point");
  });
});
