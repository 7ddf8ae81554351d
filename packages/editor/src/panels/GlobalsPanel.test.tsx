// @vitest-environment jsdom
// The Globals panel's cells: text that is not a number is refused in place in the engine's form
// and kept for correction; the engine's own refusal reads the same way.
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { cradleEditor, settled } from "../testing/harness";
import { GlobalsPanel } from "./GlobalsPanel";

afterEach(cleanup);

async function commit(label: string, text: string): Promise<HTMLInputElement> {
  fireEvent.click(screen.getByRole("button", { name: label }));
  const input = screen.getByRole("textbox", { name: label }) as HTMLInputElement;
  fireEvent.change(input, { target: { value: text } });
  await act(async () => {
    fireEvent.keyDown(input, { key: "Enter" });
  });
  return input;
}

const refusalOf = (input: HTMLInputElement) =>
  document.getElementById(input.getAttribute("aria-describedby") ?? "")?.textContent;

/** Newton's cradle loaded and settled, its Globals panel rendered. */
async function cradlePanel() {
  const h = await cradleEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <GlobalsPanel />
    </EditorContext.Provider>,
  );
  return h;
}

describe("GlobalsPanel", () => {
  it("refuses g and gravity text that is not a number as the engine refuses a value, keeping it", async () => {
    const h = await cradlePanel();
    const g = await commit("g", "9,81");
    expect(refusalOf(g)).toBe('g: must be a number (got "9,81")');
    expect(g.value).toBe("9,81");
    fireEvent.keyDown(g, { key: "Escape" });
    const gy = await commit("gravity y", "down");
    expect(refusalOf(gy)).toBe('gravity y: must be a number (got "down")');
    fireEvent.keyDown(gy, { key: "Escape" });
    // the engine's refusal of a number, in the same form
    const g2 = await commit("g", "-1");
    await waitFor(() => expect(refusalOf(g2)).toBe("g: must be a non-negative finite number (got -1)"));
    expect(g2.value).toBe("-1");
    expect(h.editor.doc.g).toBe(newtonsCradle().g);
  });

  it("drops a refused draft when a load replaces the scene: it is never applied to the next scene's g", async () => {
    const h = await cradlePanel();
    const g = await commit("g", "-1");
    await waitFor(() => expect(refusalOf(g)).toMatch(/^g: must be a non-negative/));
    await act(async () => {
      await h.editor.loadScene({ ...newtonsCradle(), g: 2 });
      await settled(h.client);
    });
    expect(screen.queryByRole("textbox", { name: "g" })).toBeNull();
    await waitFor(() => expect(screen.getByRole("button", { name: "g" }).textContent).toBe("2"));
  });
});
