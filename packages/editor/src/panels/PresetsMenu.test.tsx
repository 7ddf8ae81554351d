// @vitest-environment jsdom
// The digits field of Galperin's billiard keeps what is typed (it once snapped an emptied field to
// 1 at once, so Backspace then "6" gave "16", clamped to 7) and refuses what is not 1..7 on blur and
// on load, keeping the text (it was clamped without a word).
import { cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import type { Editor } from "../editor";
import type { SceneFile } from "../engineTypes";
import { buildPreset } from "../presets";
import { createUiStore } from "../store/uiStore";
import { testEditor } from "../testing/harness";
import { PresetsMenu } from "./PresetsMenu";

afterEach(cleanup);

function setup() {
  const loaded: SceneFile[] = [];
  const ui = createUiStore();
  const editor = { loadScene: async (s: SceneFile) => void loaded.push(s), ui } as unknown as Editor;
  render(
    <EditorContext.Provider value={editor}>
      <PresetsMenu />
    </EditorContext.Provider>,
  );
  fireEvent.change(screen.getByRole("combobox", { name: "Preset" }), { target: { value: "galperin" } });
  const field = screen.getByRole("spinbutton", { name: "Digits of π" }) as HTMLInputElement;
  return {
    loaded,
    field,
    ui,
    load: () => fireEvent.click(screen.getByRole("button", { name: "Load preset" })),
  };
}

describe("Presets menu: digits of π", () => {
  it("an emptied field stays empty while typing: Backspace then 6 gives 6", () => {
    const { loaded, field, load } = setup();
    expect(field.value).toBe("4");
    fireEvent.change(field, { target: { value: "" } });
    expect(field.value).toBe("");
    fireEvent.change(field, { target: { value: "6" } });
    expect(field.value).toBe("6");
    load();
    expect(loaded).toEqual([buildPreset("galperin", 6)]);
  });

  it("refuses digits not from 1 to 7 on blur and on load, keeping the text; loads once corrected", () => {
    const { loaded, field, load, ui } = setup();
    const refusal = () => document.getElementById(field.getAttribute("aria-describedby") ?? "")?.textContent;
    fireEvent.change(field, { target: { value: "9" } });
    load();
    expect(loaded).toEqual([]);
    expect(field.value).toBe("9");
    expect(field.getAttribute("aria-invalid")).toBe("true");
    expect(refusal()).toBe("Digits of π: must be a whole number from 1 to 7 (got 9)");
    expect(ui.getState().message?.text).toBe(refusal());
    fireEvent.change(field, { target: { value: "" } });
    fireEvent.blur(field);
    expect(field.value).toBe("");
    expect(refusal()).toBe('Digits of π: must be a whole number from 1 to 7 (got "")');
    fireEvent.change(field, { target: { value: "2.6" } });
    fireEvent.blur(field);
    expect(refusal()).toBe("Digits of π: must be a whole number from 1 to 7 (got 2.6)");
    fireEvent.change(field, { target: { value: "3" } });
    fireEvent.blur(field);
    expect(field.getAttribute("aria-invalid")).toBe("false");
    expect(ui.getState().message).toBeNull();
    load();
    expect(loaded).toEqual([buildPreset("galperin", 3)]);
  });
});

describe("Presets menu: the digits field's place", () => {
  it("is kept for every preset, but only Galperin's billiard's field can be reached, read or typed in", () => {
    const { field } = setup();
    const select = screen.getByRole("combobox", { name: "Preset" });
    expect(field.closest("label")!.style.visibility).toBe("");
    fireEvent.change(select, { target: { value: "originalDemo" } });
    // the same field, not drawn (its place kept: choosing a preset never re-wraps the header)
    expect(field.isConnected).toBe(true);
    expect(field.closest("label")!.style.visibility).toBe("hidden");
    expect(screen.queryByRole("spinbutton", { name: "Digits of π" })).toBeNull();
    // the closed list's tooltip names the chosen preset whole (a narrow window cuts it)
    expect(select.title).toBe("The original's sample (friction)");
    fireEvent.change(select, { target: { value: "galperin" } });
    expect(screen.getByRole("spinbutton", { name: "Digits of π" })).toBe(field);
    expect(select.title).toBe("Galperin's π billiard");
  });
});

describe("Presets menu: loading", () => {
  it("a loaded preset is reproducible (autosave keeps the scene it replaced) and says Undo goes back", async () => {
    const infos: string[] = [];
    const calls: unknown[] = [];
    const editor = {
      loadScene: async (_s: SceneFile, options: unknown) => {
        calls.push(options);
        return null;
      },
      info: (text: string) => infos.push(text),
    } as unknown as Editor;
    render(
      <EditorContext.Provider value={editor}>
        <PresetsMenu />
      </EditorContext.Provider>,
    );
    fireEvent.click(screen.getByRole("button", { name: "Load preset" }));
    await Promise.resolve();
    await Promise.resolve();
    // named as Save file then suggests it
    expect(calls).toEqual([{ reproducible: true, name: "original-demo.chapgame.json", preset: true }]);
    expect(infos).toHaveLength(1);
    expect(infos[0]).toMatch(/^Loaded the preset .+\. Undo returns to the scene you had\.$/);
  });

  it("Galperin's billiard is computed to its last collision: the count shows the digits of pi", async () => {
    const h = testEditor();
    render(
      <EditorContext.Provider value={h.editor}>
        <PresetsMenu />
      </EditorContext.Provider>,
    );
    fireEvent.change(screen.getByRole("combobox", { name: "Preset" }), { target: { value: "galperin" } });
    fireEvent.click(screen.getByRole("button", { name: "Load preset" }));
    await waitFor(() => expect(h.editor.ui.getState().message?.text).toMatch(/3141 collisions, up to t = /), {
      timeout: 10_000,
    });
    const c = h.client.getSnapshot().counts;
    expect(c.bodyBody + c.bodyLine).toBe(3141);
    expect(h.client.getSnapshot().computing).toBeNull();
  });
});
