// @vitest-environment jsdom
// Removing an action from the Event log takes two presses (removeConfirm.ts): a single click, or a
// double-click, once removed an action at once, and after a removal the rows moved up under the
// pointer, so a double-click removed two actions (audit of session 16). Then (audit of session 16, in
// Chromium): the wider armed button moved out from under the pointer at wide windows, which
// disarmed it; the ✕ of the next identical action stayed at "…" after a removal; a held Enter
// removed; and the focus fell to the page after a removal made from the keyboard.
import { act, cleanup, fireEvent, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { settled } from "../testing/harness";
import { ARMED_B, B, clock, twoVelocities } from "../testing/removeActionLog";
import { ARMED_MS, CONFIRM_DELAY_MS } from "./removeConfirm";

afterEach(() => {
  cleanup();
  vi.restoreAllMocks();
  vi.useRealTimers();
});

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
});
