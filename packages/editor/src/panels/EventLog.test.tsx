// @vitest-environment jsdom
// The Event log: it follows the scene while the worker computes (progress reports arrive more often
// than a log page can be read and answered: it once showed the previous scene's events for the whole
// of a long computation, every report discarding the pending page), says what each entry did,
// removes an action, selects and lights an entry's objects, moves the focus between entries, and
// counts the entries a filter shows. What an entry says and selects: EventLogEntries.test.ts.
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { EditorContext } from "../EditorContext";
import type { Editor } from "../editor";
import type { RequestMessage } from "../remote/protocol";
import { settled, testEditor } from "../testing/harness";
import { sceneOf } from "../testing/scenes";
import { EventLog } from "./EventLog";
import { CONFIRM_DELAY_MS } from "./removeConfirm";

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

/**
 * The Event log of a scene where body `body` (v = 4 from the origin) meets the segment w at
 * t = 2.25, then the point q at t = 6.75.
 */
async function bodyLinePointLog(body: string) {
  const h = testEditor();
  await h.editor.loadScene(
    sceneOf([
      { time: 0, type: "addBody", id: body, x: 0, y: 0, r: 1, m: 1, v: [4, 0] },
      { time: 0, type: "addLine", id: "w", p1: [10, -5], p2: [10, 5], kind: "segment" },
      { time: 0, type: "addPoint", id: "q", p: [-10, 0] },
    ]),
    { undoable: false },
  );
  await settled(h.client);
  return { h, log: renderLog(h.editor) };
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

  it("an action entry's ✕ removes exactly that action, as one undo step, without jumping to the entry", async () => {
    const h = testEditor();
    await h.editor.loadScene(
      sceneOf([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0.5 },
        { time: 0, type: "addBody", id: "b", x: 0, y: 10, r: 1, m: 1 },
        { time: 0.25, type: "giveVelocity", id: "a", v: [4, 0] },
        { time: 0.25, type: "giveVelocity", id: "b", v: [0, 4] },
      ]),
      { undoable: false },
    );
    await settled(h.client);
    act(() => h.editor.ui.setState({ t: 5 }));
    const log = renderLog(h.editor);
    // One button per action entry; none for a's stop.
    await waitFor(() =>
      expect(within(log).getAllByRole("button", { name: /^Remove action/ })).toHaveLength(4),
    );
    expect(within(log).getAllByText("stop")).toHaveLength(1);
    const remove = within(log).getByRole("button", {
      name: 'Remove action give velocity to "b" at t = 0.25',
    });
    // Enter on the button is the button's, not the row's (the row jumps to its time on Enter).
    fireEvent.keyDown(remove, { key: "Enter" });
    expect(h.editor.ui.getState().t).toBe(5);
    // Two presses (RemoveActionButton): the first arms it, the second, not too soon, removes.
    let now = 1000;
    vi.spyOn(performance, "now").mockImplementation(() => now);
    fireEvent.click(remove);
    now += CONFIRM_DELAY_MS;
    await act(async () => {
      fireEvent.click(remove);
      await settled(h.client);
    });
    vi.restoreAllMocks();
    expect(h.editor.doc.actions.map((a) => [a.time, a.type, "id" in a ? a.id : null])).toEqual([
      [0, "addBody", "a"],
      [0, "addBody", "b"],
      [0.25, "giveVelocity", "a"],
    ]);
    expect(h.editor.ui.getState().t).toBe(5);
    expect(h.editor.history.getState().past).toHaveLength(1);
    await waitFor(() =>
      expect(within(log).getAllByRole("button", { name: /^Remove action/ })).toHaveLength(3),
    );
    expect(
      within(log).getByRole("button", { name: 'Remove action give velocity to "a" at t = 0.25' }),
    ).toBeTruthy();
  });

  it("clicking an entry selects the object of its kind: a line's action selects the line", async () => {
    // A body named like the line: selecting "body w" for the line's entry made Delete delete it.
    const { h, log } = await bodyLinePointLog("w");
    const row = async (text: string) => (await within(log).findByText(text)).closest("tr")!;
    fireEvent.click(await row("action: add line"));
    expect(h.editor.ui.getState().selection).toEqual({ kind: "line", id: "w" });
    fireEvent.click(await row("action: add point"));
    expect(h.editor.ui.getState().selection).toEqual({ kind: "point", id: "q" });
    fireEvent.click(await row("action: add body"));
    expect(h.editor.ui.getState().selection).toEqual({ kind: "body", id: "w" });
    fireEvent.click(await row("body–line"));
    expect(h.editor.ui.getState().selection).toEqual({ kind: "body", id: "w" });
    // Both participants lit, each with its kind (by id alone the body and the line "w" were both lit
    // by an entry naming either).
    expect(h.editor.ui.getState().highlight).toEqual(["body:w", "line:w"]);
    fireEvent.click(await row("action: add line"));
    expect(h.editor.ui.getState().highlight).toEqual(["line:w"]);
  });

  it("the clicked entry, the one Event details shows, is marked selected; the others are not", async () => {
    const { log } = await bodyLinePointLog("w");
    const row = async (text: string) => (await within(log).findByText(text)).closest("tr")!;
    const selected = () =>
      Array.from(log.querySelectorAll("tbody tr[aria-selected='true']")).map((r) => r.textContent);
    expect(selected()).toEqual([]);
    fireEvent.click(await row("body–line"));
    await waitFor(() => expect(selected()).toHaveLength(1));
    expect(selected()[0]).toMatch(/body–line/);
    expect((await row("body–line")).className).toMatch(/\bchosen\b/);
    fireEvent.click(await row("action: add point"));
    await waitFor(() => expect(selected()[0]).toMatch(/action: add point/));
    expect(selected()).toHaveLength(1);
  });

  it("↓ and ↑ move the focus between entries, past the spacer rows; at the ends they do nothing", async () => {
    const { log } = await bodyLinePointLog("w");
    await within(log).findByText("body–line");
    const rows = Array.from(log.querySelectorAll<HTMLTableRowElement>("tbody tr[tabindex='0']"));
    expect(rows.length).toBeGreaterThan(2);
    rows[0]!.focus();
    fireEvent.keyDown(rows[0]!, { key: "ArrowDown" });
    expect(document.activeElement).toBe(rows[1]);
    fireEvent.keyDown(rows[1]!, { key: "ArrowUp" });
    expect(document.activeElement).toBe(rows[0]);
    fireEvent.keyDown(rows[0]!, { key: "ArrowUp" });
    expect(document.activeElement).toBe(rows[0]);
    const last = rows[rows.length - 1]!;
    last.focus();
    fireEvent.keyDown(last, { key: "ArrowDown" });
    expect(document.activeElement).toBe(last);
  });

  it("Enter on an entry keeps the focus on that entry when the log is read again around its time", async () => {
    // audit of session 20: rows are kept by position, and the page read around the new time put
    // another entry in the focused row (a screen reader then read that one)
    const h = testEditor();
    await h.editor.loadScene(
      sceneOf([
        { time: 0, type: "addLine", id: "L", p1: [-10, -5], p2: [-10, 5], kind: "line" },
        { time: 0, type: "addLine", id: "R", p1: [10, -5], p2: [10, 5], kind: "line" },
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [9, 0] },
      ]),
      { undoable: false },
    );
    await settled(h.client);
    await h.editor.goTo(400); // a bounce every 2 s: far more entries than one page holds
    await settled(h.client);
    h.editor.ui.setState({ t: 0 });
    const log = renderLog(h.editor);
    await within(log).findAllByText("body–line");
    const rows = () => Array.from(log.querySelectorAll<HTMLTableRowElement>("tbody tr[tabindex='0']"));
    const row = rows().at(-1)!;
    const time = row.cells[0]!.textContent;
    act(() => row.focus());
    fireEvent.keyDown(row, { key: "Enter" });
    await waitFor(() => expect(h.editor.ui.getState().t).toBeGreaterThan(0));
    // the page is read again around the new time: the entry moves up the table, and the focus with it
    await waitFor(() => expect(rows().at(-1)!.cells[0]!.textContent).not.toBe(time));
    await waitFor(() =>
      expect((document.activeElement as HTMLTableRowElement).cells[0]!.textContent).toBe(time),
    );
  });

  it("the participants of a clicked entry stay lit only while the time stays at it (→ moved on, the canvas kept them)", async () => {
    // a (v = 4) meets the segment w at t = 2.25, then the point q at t = 6.75.
    const { h, log } = await bodyLinePointLog("a");
    fireEvent.click((await within(log).findByText("body–line")).closest("tr")!);
    expect(h.editor.ui.getState()).toMatchObject({ t: 2.25, highlight: ["body:a", "line:w"] });
    await act(() => h.editor.stepEvent(1));
    expect(h.editor.ui.getState()).toMatchObject({ t: 6.75, highlight: [] });
    // Clicking another entry moves the time and lights that entry's participants.
    fireEvent.click((await within(log).findByText("body–point")).closest("tr")!);
    expect(h.editor.ui.getState()).toMatchObject({ t: 6.75, highlight: ["body:a", "point:q"] });
    fireEvent.click((await within(log).findByText("body–line")).closest("tr")!);
    expect(h.editor.ui.getState()).toMatchObject({ t: 2.25, highlight: ["body:a", "line:w"] });
  });

  it("filtered by a body, the header counts the body's entries shown, then the log's total", async () => {
    const h = testEditor();
    await h.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(h.client);
    act(() => h.editor.ui.setState({ t: 0.5, eventFilter: "c3" }));
    const log = renderLog(h.editor);
    const total = h.client.getSnapshot().eventCount;
    expect(total).toBe(11); // 6 actions at t = 0, 5 collisions at t = 1
    // c3: its add body at 0 and its two collisions at 1
    await waitFor(() => expect(within(log).getAllByText(/c3/)).toHaveLength(3));
    expect(screen.getByRole("heading", { name: /Event log/ }).textContent).toBe(
      `Event log (3 shown for c3 · ${total} in all)`,
    );
  });
});
