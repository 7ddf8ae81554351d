// @vitest-environment jsdom
// The Event details panel: the hint before any entry is chosen; a click (or Enter) on a row of the
// Event log shows that entry's exact before/after velocities; participants select their objects;
// an edit that recomputes the entry away says so, and an undo brings the detail back; Previous /
// Next entry step through the log, and say so at its ends.

import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import type { Editor } from "../editor";
import { refKey } from "../remote/eventDetail";
import { settled, testEditor } from "../testing/harness";
import { sceneOf } from "../testing/scenes";
import { EventDetails, participantSelection } from "./EventDetails";
import { EventLog } from "./EventLog";
import { NO_EARLIER, NO_LATER } from "./entryStep";

afterEach(cleanup);

/** a (m = 1, v = 4) meets b (m = 3, at rest) head-on at t = 2: after, a at -2 and b at 2. */
async function headOn() {
  const h = testEditor();
  await h.editor.loadScene(
    sceneOf(
      [
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [4, 0] },
        { time: 0, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 3 },
      ],
      0,
    ),
    { undoable: false },
  );
  await settled(h.client);
  return h;
}

function renderPanels(editor: Editor) {
  render(
    <EditorContext.Provider value={editor}>
      <EventLog />
      <EventDetails />
    </EditorContext.Provider>,
  );
  const panel = screen.getByRole("region", { name: "Event details" });
  return { log: screen.getByRole("table", { name: "Event log" }), panel };
}

/** The text of each cell of the velocities table, row by row (header first). */
function velocityRows(panel: HTMLElement): string[][] {
  const table = within(panel).getByRole("table", { name: "Velocities before and after" });
  return [...table.querySelectorAll("tr")].map((tr) => [...tr.children].map((c) => c.textContent ?? ""));
}

/** The dl's fields as { name: value }. */
function fields(panel: HTMLElement): Record<string, string> {
  const out: Record<string, string> = {};
  for (const dt of panel.querySelectorAll("dt"))
    out[dt.textContent ?? ""] = dt.nextElementSibling?.textContent ?? "";
  return out;
}

describe("EventDetails", () => {
  it("without a selected entry, says how to choose one", async () => {
    const h = await headOn();
    const { panel } = renderPanels(h.editor);
    expect(within(panel).getByText("Select an entry of the Event log to see its details.")).toBeTruthy();
    expect(within(panel).queryByRole("table")).toBeNull();
  });

  it("a click on the body–body row shows its time, kind, contact, impulse and exact velocities", async () => {
    const h = await headOn();
    const { log, panel } = renderPanels(h.editor);
    const cell = await within(log).findByText("body–body");
    fireEvent.click(cell.closest("tr") as HTMLElement);
    expect(h.editor.ui.getState().selectedEvent).toEqual({ time: 2, type: "bodyBody", ids: ["a", "b"] });
    await waitFor(() => expect(within(panel).queryByText("Reading…")).toBeNull());
    expect(fields(panel)).toEqual({
      time: "2",
      kind: "body–body",
      participants: "a, b",
      "contact point": "(9, 0)",
      normal: "(1, 0)",
      impulse: "6",
    });
    expect(velocityRows(panel)).toEqual([
      ["body", "v before", "v after", "|v| before", "|v| after"],
      ["a", "(4, 0)", "(-2, 0)", "4", "2"],
      ["b", "(0, 0)", "(2, 0)", "0", "2"],
    ]);
    // a participant selects its body
    fireEvent.click(within(panel).getByRole("button", { name: "b" }));
    expect(h.editor.ui.getState().selection).toEqual({ kind: "body", id: "b" });
  });

  it("Enter on an action row shows the action's body before (none) and after its addition", async () => {
    const h = await headOn();
    const { log, panel } = renderPanels(h.editor);
    const rows = await within(log).findAllByText("action: add body");
    const row = rows[1]?.closest("tr") as HTMLElement; // b's
    row.focus();
    fireEvent.keyDown(row, { key: "Enter" });
    await waitFor(() => expect(fields(panel).kind).toBe("action: add body"));
    expect(fields(panel)).toMatchObject({ participants: "b", "contact point": "—", impulse: "—" });
    expect(velocityRows(panel)[1]).toEqual(["b", "—", "(0, 0)", "—", "0"]);
  });

  it("an edit that removes the entry says it is gone; an undo brings the detail back", async () => {
    const h = await headOn();
    const { log, panel } = renderPanels(h.editor);
    fireEvent.click((await within(log).findByText("body–body")).closest("tr") as HTMLElement);
    await waitFor(() => expect(velocityRows(panel)[1]).toEqual(["a", "(4, 0)", "(-2, 0)", "4", "2"]));
    act(() => h.editor.ui.setState({ t: 1 }));
    await act(async () => {
      await h.editor.giveVelocity("a", [0, 4]); // a turns away at t = 1: no collision
      await settled(h.client);
    });
    await waitFor(() =>
      expect(within(panel).getByRole("status").textContent).toMatch(/no longer in the history/),
    );
    await act(async () => {
      await h.editor.undo();
      await settled(h.client);
    });
    await waitFor(() => expect(velocityRows(panel)[2]).toEqual(["b", "(0, 0)", "(2, 0)", "0", "2"]));
  });

  it("Previous / Next entry step through the log from the selected entry, greyed out at its ends", async () => {
    const h = await headOn();
    const { log, panel } = renderPanels(h.editor);
    const prev = within(panel).getByRole("button", { name: "◀ Previous entry" }) as HTMLButtonElement;
    const next = within(panel).getByRole("button", { name: "Next entry ▶" }) as HTMLButtonElement;
    // greyed out but focusable (aria-disabled): a disabled button dropped the keyboard focus (audit)
    const off = (b: HTMLButtonElement) => b.getAttribute("aria-disabled") === "true" && !b.disabled;
    expect(off(prev) && off(next)).toBe(true);
    fireEvent.click((await within(log).findByText("body–body")).closest("tr") as HTMLElement);
    await waitFor(() => expect(off(prev)).toBe(false));
    // the log: add a, add b (t = 0), the collision (t = 2); nothing after it: Next is greyed out and
    // says why (audit of session 20: it stayed enabled and seemed to do nothing)
    expect(off(next)).toBe(true);
    expect(next.title).toBe(NO_LATER);
    const state = () => h.editor.ui.getState();
    expect(state().selectedEvent).toMatchObject({ time: 2, type: "bodyBody" });
    fireEvent.click(prev);
    await waitFor(() => expect(state().selectedEvent).toMatchObject({ ids: ["b"] }));
    expect(state()).toMatchObject({
      t: 0,
      playing: false,
      selection: { kind: "body", id: "b" },
      highlight: ["body:b"],
      selectedEvent: { time: 0, type: "action", action: "addBody", ids: ["b"] },
    });
    await waitFor(() => expect(fields(panel).participants).toBe("b"));
    fireEvent.click(prev);
    await waitFor(() => expect(fields(panel).participants).toBe("a"));
    await waitFor(() => expect(off(prev)).toBe(true));
    expect(prev.title).toBe(NO_EARLIER);
    expect(off(next)).toBe(false);
    // greyed out, it does nothing
    fireEvent.click(prev);
    await new Promise((r) => setTimeout(r, 50));
    expect(state().selectedEvent).toMatchObject({ ids: ["a"] });
    expect(state().selectedEvent).toMatchObject({ ids: ["a"] });
  });

  it("loading another scene forgets the selected entry (it belonged to the other scene's log)", async () => {
    const h = await headOn();
    const { log, panel } = renderPanels(h.editor);
    fireEvent.click((await within(log).findByText("body–body")).closest("tr") as HTMLElement);
    await waitFor(() => expect(fields(panel).kind).toBe("body–body"));
    await act(async () => {
      await h.editor.loadScene(newtonsCradle());
      await settled(h.client);
    });
    expect(h.editor.ui.getState().selectedEvent).toBeNull();
    expect(within(panel).getByText("Select an entry of the Event log to see its details.")).toBeTruthy();
  });

  it("participantSelection: bodies, then the line or point of a collision; an action's object", () => {
    const base = { time: 1, point: null, normal: null, impulse: null, bodies: [] };
    const hit = { time: 1, point: [0, 0] as const, normal: [1, 0] as const, impulse: 1, bodies: [] };
    expect(participantSelection({ ...hit, type: "bodyLine", ids: ["a", "w"] }, 1)).toEqual({
      kind: "line",
      id: "w",
    });
    expect(participantSelection({ ...hit, type: "bodyPoint", ids: ["a", "q"] }, 0)).toEqual({
      kind: "body",
      id: "a",
    });
    expect(participantSelection({ ...hit, type: "bodyBody", ids: ["a", "b"] }, 1)).toEqual({
      kind: "body",
      id: "b",
    });
    expect(participantSelection({ ...base, type: "action", action: "addPoint", ids: ["q"] }, 0)).toEqual({
      kind: "point",
      id: "q",
    });
    expect(refKey(null)).toBe("");
    expect(refKey({ time: 1, type: "stop", ids: ["a"] })).not.toBe(
      refKey({ time: 1, type: "stop", ids: ["b"] }),
    );
  });
});
