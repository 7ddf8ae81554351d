// @vitest-environment jsdom
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { cradleEditor } from "../testing/harness";
import { layOutText, restoreTextLayout } from "../testing/textLayout";
import { MessageBar } from "./MessageBar";

afterEach(() => {
  cleanup();
  restoreTextLayout();
});

async function setup() {
  layOutText();
  const h = await cradleEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <MessageBar />
    </EditorContext.Provider>,
  );
  return h.editor;
}

const toggle = () => screen.queryByRole("button", { name: /^(More|Less)$/ });
const LONG = "A refusal longer than its line can hold.";

describe("MessageBar", () => {
  it("offers More only for a message cut at its line; More shows it whole, Less takes it back", async () => {
    const editor = await setup();
    act(() => editor.ui.setState({ message: { text: "Short.", tone: "info" } }));
    expect(screen.getByRole("status").textContent).toContain("Short.");
    expect(toggle()).toBeNull();
    act(() => editor.ui.setState({ message: { text: LONG, tone: "error" } }));
    const alert = screen.getByRole("alert");
    expect(toggle()?.textContent).toBe("More");
    expect(toggle()?.getAttribute("aria-expanded")).toBe("false");
    expect(alert.classList.contains("open")).toBe(false);
    fireEvent.click(toggle()!);
    expect(toggle()?.textContent).toBe("Less");
    expect(toggle()?.getAttribute("aria-expanded")).toBe("true");
    expect(alert.classList.contains("open")).toBe(true);
    fireEvent.click(toggle()!);
    expect(toggle()?.textContent).toBe("More");
    expect(alert.classList.contains("open")).toBe(false);
  });

  it("shows the next message on its line first, even with the same text; ✕ takes it down", async () => {
    const editor = await setup();
    act(() => editor.ui.setState({ message: { text: LONG, tone: "error" } }));
    fireEvent.click(toggle()!);
    expect(screen.getByRole("alert").classList.contains("open")).toBe(true);
    act(() => editor.ui.setState({ message: { text: LONG, tone: "error" } }));
    expect(screen.getByRole("alert").classList.contains("open")).toBe(false);
    expect(toggle()?.textContent).toBe("More");
    fireEvent.click(screen.getByRole("button", { name: "Dismiss message" }));
    expect(editor.ui.getState().message).toBeNull();
    expect(screen.queryByRole("alert")).toBeNull();
  });
});
