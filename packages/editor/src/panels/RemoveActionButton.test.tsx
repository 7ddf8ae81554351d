// @vitest-environment jsdom
// Removing an action from the Event log takes two presses (removeConfirm.ts): a single click, or a
// double-click, once removed an action at once, and after a removal the rows moved up under the
// pointer, so a double-click removed two actions (audit of session 16). Then (audit of session 16, in
// Chromium): the wider armed button moved out from under the pointer at wide windows, which
// disarmed it; the ✕ of the next identical action stayed at "…" after a removal; a held Enter
// removed; and the focus fell to the page after a removal made from the keyboard.
import { act, cleanup, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { EditorContext } from "../EditorContext";
import type { Action } from "../engineTypes";
import { settled, testEditor } from "../testing/harness";
import { sceneOf } from "../testing/scenes";
import { EventLog } from "./EventLog";
import { ARMED_MS, CONFIRM_DELAY_MS } from "./removeConfirm";

afterEach(() => {
  cleanup();
  vi.restoreAllMocks();
  vi.useRealTimers();
});

/** The clock the button reads (performance.now), moved by the test. */
function clock() {
  let now = 10_000;
  vi.spyOn(performance, "now").mockImplementation(() => now);
  return (ms: number) => {
    now += ms;
  };
}

/** The Event log of a scene of `actions` at t = 5, once it shows `buttons` remove buttons. */
async function logOf(actions: Action[], buttons: number) {
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
async function twoVelocities() {
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

/** Two identical actions (update body "a" at t = 0.5, as editing a's vx then vy there makes). */
async function twoUpdates() {
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

const B = 'Remove action give velocity to "b" at t = 0.25';
const ARMED_B = 'Confirm: remove action give velocity to "b" at t = 0.25 (press again; Escape keeps it)';

describe("RemoveActionButton", () => {
  it("a single click only arms the button; the confirm removes the action, says so, and Undo brings it back", async () => {
    const tick = clock();
    const { h, log, velocities } = await twoVelocities();
    const button = within(log).getByRole("button", { name: B });
    fireEvent.click(button);
    await settled(h.client);
    expect(velocities()).toEqual(["a", "b"]);
    expect(button.textContent).toContain("Remove?");
    expect(button.getAttribute("aria-label")).toBe(ARMED_B);
    expect(h.editor.ui.getState().t).toBe(5); // the press does not reach the row
    tick(CONFIRM_DELAY_MS);
    await act(async () => {
      fireEvent.click(button);
      await settled(h.client);
    });
    expect(velocities()).toEqual(["a"]);
    expect(h.editor.ui.getState().message).toEqual({
      text: 'Removed give velocity to "b" at t = 0.25 s from the scene (Undo brings it back).',
      tone: "info",
    });
    await act(async () => {
      await h.editor.undo();
      await settled(h.client);
    });
    expect(velocities()).toEqual(["a", "b"]);
    expect(h.editor.ui.getState().message?.text).toBe(
      'Undone: the removal of give velocity to "b" at t = 0.25 s.',
    );
  });

  it("Escape, leaving the button (pointer or focus) and the timeout disarm it", async () => {
    const tick = clock();
    const { h, log, velocities } = await twoVelocities();
    const button = () => within(log).getByRole("button", { name: /give velocity to "b"/ });
    const disarmers: [string, () => void][] = [
      ["Escape", () => fireEvent.keyDown(button(), { key: "Escape" })],
      ["pointer", () => fireEvent.mouseLeave(button())],
      ["focus", () => fireEvent.blur(button())],
    ];
    for (const [, disarmIt] of disarmers) {
      fireEvent.click(button());
      expect(button().getAttribute("aria-label")).toBe(ARMED_B);
      act(disarmIt);
      expect(button().getAttribute("aria-label")).toBe(B);
      tick(CONFIRM_DELAY_MS);
      fireEvent.click(button()); // arms again: nothing removed
      await settled(h.client);
      expect(velocities()).toEqual(["a", "b"]);
      act(() => fireEvent.keyDown(button(), { key: "Escape" }));
    }
    vi.useFakeTimers({ toFake: ["setTimeout", "clearTimeout"] });
    fireEvent.click(button());
    expect(button().getAttribute("aria-label")).toBe(ARMED_B);
    act(() => vi.advanceTimersByTime(ARMED_MS));
    expect(button().getAttribute("aria-label")).toBe(B);
  });

  it("armed, the log's one polite live region says what a second press removes; disarmed, it says nothing", async () => {
    const tick = clock();
    const { h, log, velocities } = await twoVelocities();
    // one region for the log (none per row), visually hidden, empty at rest
    const regions = screen.getAllByRole("status");
    expect(regions).toHaveLength(1);
    const region = regions[0] as HTMLElement;
    expect(region.getAttribute("aria-live")).toBe("polite");
    expect(region.className).toBe("visually-hidden");
    expect(log.contains(region)).toBe(false);
    expect(region.textContent).toBe("");
    const button = (name: RegExp) => within(log).getByRole("button", { name });
    const PROMPT_B = 'Press again to remove action give velocity to "b" at t = 0.25';
    fireEvent.click(button(/give velocity to "b"/));
    expect(region.textContent).toBe(PROMPT_B);
    act(() => fireEvent.keyDown(button(/give velocity to "b"/), { key: "Escape" }));
    expect(region.textContent).toBe("");
    // another button armed since keeps its prompt when the first disarms
    fireEvent.click(button(/give velocity to "b"/));
    fireEvent.click(button(/give velocity to "a"/));
    expect(region.textContent).toBe('Press again to remove action give velocity to "a" at t = 0.25');
    act(() => fireEvent.keyDown(button(/give velocity to "b"/), { key: "Escape" }));
    expect(region.textContent).toBe('Press again to remove action give velocity to "a" at t = 0.25');
    act(() => fireEvent.mouseLeave(button(/give velocity to "a"/)));
    expect(region.textContent).toBe("");
    // the confirming press empties it
    fireEvent.click(button(/give velocity to "b"/));
    expect(region.textContent).toBe(PROMPT_B);
    tick(CONFIRM_DELAY_MS);
    await act(async () => {
      fireEvent.click(button(/give velocity to "b"/));
      await settled(h.client);
    });
    expect(velocities()).toEqual(["a"]);
    expect(region.textContent).toBe("");
  });

  it("a double-click removes nothing, and a press on the row that moved up after a removal only arms it", async () => {
    const tick = clock();
    const { h, log, velocities } = await twoVelocities();
    const button = within(log).getByRole("button", { name: B });
    await act(async () => {
      fireEvent.click(button, { detail: 1 });
      tick(120);
      fireEvent.click(button, { detail: 2 });
      fireEvent.doubleClick(button);
      await settled(h.client);
    });
    expect(velocities()).toEqual(["a", "b"]);
    expect(button.getAttribute("aria-label")).toBe(ARMED_B); // still armed: a later click confirms
    act(() => fireEvent.keyDown(button, { key: "Escape" }));
    // the confirm, then at once more presses where the pointer is: one action removed
    const a = within(log).getByRole("button", { name: 'Remove action give velocity to "a" at t = 0.25' });
    const row = a.closest("tr")!;
    const index = [...row.parentElement!.children].indexOf(row);
    fireEvent.click(a);
    tick(CONFIRM_DELAY_MS);
    await act(async () => {
      fireEvent.click(a);
      await settled(h.client);
    });
    expect(velocities()).toEqual(["b"]);
    const there = () => row.parentElement!.children[index]!;
    await waitFor(() => expect(there().textContent).toMatch(/velocityb/), { timeout: 3000 });
    // the row where a's entry was now shows b's: its button is at rest, a press only arms it
    const moved = there().querySelector("button")!;
    expect(moved.getAttribute("aria-label")).toBe(B);
    tick(CONFIRM_DELAY_MS);
    await act(async () => {
      fireEvent.click(moved);
      await settled(h.client);
    });
    expect(velocities()).toEqual(["b"]);
    expect(moved.getAttribute("aria-label")).toBe(ARMED_B);
  });

  it("keyboard: the button takes the focus, and Enter on it is the button's (the row does not jump)", async () => {
    const tick = clock();
    const { h, log, velocities } = await twoVelocities();
    const button = within(log).getByRole("button", { name: B });
    button.focus();
    expect(document.activeElement).toBe(button);
    fireEvent.keyDown(button, { key: "Enter" }); // a button's Enter is its click (below)
    expect(h.editor.ui.getState().t).toBe(5);
    fireEvent.click(button);
    expect(button.getAttribute("aria-label")).toBe(ARMED_B);
    tick(CONFIRM_DELAY_MS);
    await act(async () => {
      fireEvent.click(button);
      await settled(h.client);
    });
    expect(velocities()).toEqual(["a"]);
  });

  it("armed, the button keeps what it shows in the layout: 'Remove?' is a part of it drawn outside the flow", async () => {
    clock();
    const { log } = await twoVelocities();
    const button = within(log).getByRole("button", { name: B });
    const rest = button.textContent;
    fireEvent.click(button);
    const prompt = button.querySelector(".log-remove-prompt");
    expect(prompt?.textContent).toBe("Remove?"); // inside the button: pointing at it is pointing at the button
    expect(prompt?.getAttribute("aria-hidden")).toBe("true"); // the name says it already
    expect(button.textContent?.replace("Remove?", "")).toBe(rest); // the rest of the button is unchanged
    // the stylesheet takes the prompt out of the layout (e2e editor-views checks the box in Chromium)
  });

  it("removing the first of two identical actions leaves the second's ✕ at rest, and it removes", async () => {
    const tick = clock();
    const { h, log, updates } = await twoUpdates();
    const first = within(log).getAllByRole("button", {
      name: 'Remove action update body "a" at t = 0.5',
    })[0]!;
    fireEvent.click(first);
    tick(CONFIRM_DELAY_MS);
    await act(async () => {
      fireEvent.click(first);
      await settled(h.client);
    });
    expect(updates()).toEqual([[10, 20]]);
    // the log shows the scene without it: one update entry, in the row the first one had
    await waitFor(() => expect(within(log).getAllByText("action: update body")).toHaveLength(1));
    const second = within(log).getByRole("button", { name: /update body "a"/ });
    expect(second.getAttribute("aria-label")).toBe('Remove action update body "a" at t = 0.5');
    expect(second.getAttribute("aria-disabled")).toBe("false");
    expect(second.textContent).toBe("✕");
    fireEvent.click(second);
    tick(CONFIRM_DELAY_MS);
    await act(async () => {
      fireEvent.click(second);
      await settled(h.client);
    });
    expect(updates()).toEqual([]);
  });

  it("a held key's repeats never press it (Enter presses on keydown; only the first counts)", async () => {
    clock();
    const { log } = await twoVelocities();
    const button = within(log).getByRole("button", { name: B });
    // fireEvent returns false when the handler prevented the default action (the press)
    expect(fireEvent.keyDown(button, { key: "Enter" })).toBe(true);
    expect(fireEvent.keyDown(button, { key: "Enter", repeat: true })).toBe(false);
    expect(fireEvent.keyDown(button, { key: " ", repeat: true })).toBe(false);
    expect(fireEvent.keyDown(button, { key: "Escape", repeat: true })).toBe(true);
  });

  it("a removal from the keyboard moves the focus to the next action's ✕, else the previous one's", async () => {
    const tick = clock();
    const { h, log, velocities } = await twoVelocities();
    const removeFocused = async (name: string) => {
      const button = within(log).getByRole("button", { name });
      button.focus();
      fireEvent.click(button);
      tick(CONFIRM_DELAY_MS);
      await act(async () => {
        fireEvent.click(button);
        await settled(h.client);
      });
    };
    // b is the last action: the focus goes to a's ✕ (the previous action)
    await removeFocused(B);
    expect(velocities()).toEqual(["a"]);
    await waitFor(() =>
      expect(document.activeElement?.getAttribute("aria-label")).toBe(
        'Remove action give velocity to "a" at t = 0.25',
      ),
    );
    // a's, with b's after it: the focus goes to b's ✕ (the next action, at a's index now)
    await act(async () => {
      await h.editor.undo();
      await settled(h.client);
    });
    await waitFor(() =>
      expect(within(log).getAllByRole("button", { name: /^Remove action/ })).toHaveLength(4),
    );
    await removeFocused('Remove action give velocity to "a" at t = 0.25');
    expect(velocities()).toEqual(["b"]);
    await waitFor(() => expect(document.activeElement?.getAttribute("aria-label")).toBe(B));
  });
});
