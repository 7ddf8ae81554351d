// @vitest-environment jsdom
// The Event log's remove button from the keyboard (its own Enter, a held key's repeats, the focus
// after a removal), its layout when armed, and the ✕ of the next identical action after a removal
// (audits of session 16; RemoveActionButton.test.tsx has the two presses a removal takes).
import { act, cleanup, fireEvent, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { settled } from "../testing/harness";
import { ARMED_B, B, clock, twoUpdates, twoVelocities } from "../testing/removeActionLog";
import { CONFIRM_DELAY_MS } from "./removeConfirm";

afterEach(() => {
  cleanup();
  vi.restoreAllMocks();
  vi.useRealTimers();
});

describe("RemoveActionButton from the keyboard, and after a removal", () => {
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
    // the stylesheet takes the prompt out of the layout (e2e editor-remove-action checks the box in Chromium)
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
