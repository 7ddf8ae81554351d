/**
 * Test fixtures of the Event log's remove buttons (panels/RemoveActionButton.tsx): a clock the
 * buttons read, moved by the test, and Event logs of small scenes with their action entries.
 */
import { act, render, screen, waitFor, within } from "@testing-library/react";
import { expect, vi } from "vitest";
import { EditorContext } from "../EditorContext";
import type { Action } from "../engineTypes";
import { EventLog } from "../panels/EventLog";
import { settled, testEditor } from "./harness";
import { sceneOf } from "./scenes";

/** The clock the button reads (performance.now), moved by the test. */
export function clock() {
  let now = 10_000;
  vi.spyOn(performance, "now").mockImplementation(() => now);
  return (ms: number) => {
    now += ms;
  };
}

/** The Event log of a scene of `actions` at t = 5, once it shows `buttons` remove buttons. */
export async function logOf(actions: Action[], buttons: number) {
  const h = testEditor();
  await h.editor.loadScene(sceneOf(actions), { undoable: false });
  await settled(h.client);
  act(() => h.editor.ui.setState({ t: 5 }));
  render(
    <EditorContext.Provider value={h.editor}>
      <EventLog />
    </EditorContext.Provider>,
  );
  const log = screen.getByRole("table", { name: "Event log" });
  await waitFor(() =>
    expect(within(log).getAllByRole("button", { name: /^Remove action/ })).toHaveLength(buttons),
  );
  return { h, log };
}

/** Two discs, each given a velocity at t = 0.25 (two action entries at the same time); the log at t = 5. */
export async function twoVelocities() {
  const { h, log } = await logOf(
    [
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
      { time: 0, type: "addBody", id: "b", x: 0, y: 10, r: 1, m: 1 },
      { time: 0.25, type: "giveVelocity", id: "a", v: [4, 0] },
      { time: 0.25, type: "giveVelocity", id: "b", v: [0, 4] },
    ],
    4,
  );
  const velocities = () => h.editor.doc.actions.filter((a) => a.type === "giveVelocity").map((a) => a.id);
  return { h, log, velocities };
}

/** Two identical actions (update body "a" at t = 0.5, as editing a's vx then vy there made before
 *  such edits merged into one action, doc/mergeEdit.ts: a scene saved then). */
export async function twoUpdates() {
  const { h, log } = await logOf(
    [
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
      { time: 0.5, type: "updateBody", id: "a", v: [10, 0] },
      { time: 0.5, type: "updateBody", id: "a", v: [10, 20] },
    ],
    3,
  );
  const updates = () => h.editor.doc.actions.filter((a) => a.type === "updateBody").map((a) => a.v);
  return { h, log, updates };
}

export const B = 'Remove action give velocity to "b" at t = 0.25';
export const ARMED_B =
  'Confirm: remove action give velocity to "b" at t = 0.25 (press again; Escape keeps it)';
