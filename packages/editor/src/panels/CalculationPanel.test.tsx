// @vitest-environment jsdom
// The Calculation settings: Enter applies a field (it applied only on leaving it), and a refused
// value is put back with a message (it was put back without a word).
import { dilutedGas } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { CalculationPanel } from "./CalculationPanel";

afterEach(cleanup);

function renderPanel() {
  const h = testEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <CalculationPanel />
    </EditorContext.Provider>,
  );
  return h.editor;
}

describe("CalculationPanel", () => {
  it("Enter applies Seconds ahead and Events ahead", () => {
    const editor = renderPanel();
    const seconds = screen.getByRole("textbox", { name: "Seconds ahead" }) as HTMLInputElement;
    seconds.focus();
    fireEvent.change(seconds, { target: { value: "25" } });
    fireEvent.keyDown(seconds, { key: "Enter" });
    expect(editor.ui.getState().calc.seconds).toBe(25);
    const events = screen.getByRole("textbox", { name: "Events ahead" }) as HTMLInputElement;
    events.focus();
    fireEvent.change(events, { target: { value: "300" } });
    fireEvent.keyDown(events, { key: "Enter" });
    expect(editor.ui.getState().calc.events).toBe(300);
    expect(editor.ui.getState().message).toBeNull();
  });

  it("keeps a refused value in its field, says why beside it, and applies the correction", () => {
    const editor = renderPanel();
    const before = editor.ui.getState().calc.seconds;
    const seconds = screen.getByRole("textbox", { name: "Seconds ahead" }) as HTMLInputElement;
    seconds.focus();
    fireEvent.change(seconds, { target: { value: "abc" } });
    fireEvent.keyDown(seconds, { key: "Enter" });
    // the text typed stays (it was put back to the setting, the text lost), the refusal beside it
    expect(seconds.value).toBe("abc");
    expect(editor.ui.getState().calc.seconds).toBe(before);
    const refusal = `Seconds ahead: must be a positive finite number (got "abc"): Compute still uses ${before} s`;
    expect(editor.ui.getState().message).toEqual({ text: refusal, tone: "error" });
    expect(seconds.getAttribute("aria-invalid")).toBe("true");
    expect(document.getElementById(seconds.getAttribute("aria-describedby") ?? "")?.textContent).toBe(
      refusal,
    );
    // leaving the field with the same text does not refuse it again; the corrected text applies
    fireEvent.blur(seconds);
    expect(seconds.value).toBe("abc");
    fireEvent.change(seconds, { target: { value: "abc5" } });
    fireEvent.change(seconds, { target: { value: "5" } });
    fireEvent.keyDown(seconds, { key: "Enter" });
    expect(editor.ui.getState().calc.seconds).toBe(5);
    expect(seconds.value).toBe("5");
    expect(seconds.getAttribute("aria-invalid")).toBe("false");
    expect(seconds.getAttribute("aria-describedby")).toBeNull();
    expect(editor.ui.getState().message).toBeNull();
    const events = screen.getByRole("textbox", { name: "Events ahead" }) as HTMLInputElement;
    events.focus();
    fireEvent.change(events, { target: { value: "2.5" } });
    fireEvent.blur(events);
    expect(editor.ui.getState().message?.text).toMatch(
      /^Events ahead: must be a whole number of at least 1 \(got 2\.5\): Compute still uses \d+ events$/,
    );
  });

  it("an accepted value takes down its field's refusal, and only that", () => {
    const editor = renderPanel();
    const seconds = screen.getByRole("textbox", { name: "Seconds ahead" }) as HTMLInputElement;
    const events = screen.getByRole("textbox", { name: "Events ahead" }) as HTMLInputElement;
    const type = (input: HTMLInputElement, value: string) => {
      input.focus();
      fireEvent.change(input, { target: { value } });
      fireEvent.keyDown(input, { key: "Enter" });
    };
    type(seconds, "1e999");
    expect(editor.ui.getState().message?.text).toMatch(/^Seconds ahead: must be /);
    type(events, "300"); // another field's value: the refusal of Seconds ahead stays
    expect(editor.ui.getState().message?.text).toMatch(/^Seconds ahead: must be /);
    type(seconds, "20");
    expect(editor.ui.getState().calc.seconds).toBe(20);
    expect(editor.ui.getState().message).toBeNull();
    act(() => editor.info("Something else."));
    type(events, "400"); // a message not about the field stays
    expect(editor.ui.getState().message?.text).toBe("Something else.");
  });

  it("Compute pressed from the keyboard keeps the focus while it computes (greyed out, not disabled)", async () => {
    const h = testEditor();
    await h.editor.loadScene(dilutedGas({ n: 400, packing: 0.1, seed: 2 }), { undoable: false });
    await settled(h.client);
    h.editor.ui.setState((s) => ({ calc: { ...s.calc, seconds: 5000 } }));
    render(
      <EditorContext.Provider value={h.editor}>
        <CalculationPanel />
      </EditorContext.Provider>,
    );
    const compute = screen.getByRole("button", { name: "Compute" }) as HTMLButtonElement;
    act(() => compute.focus());
    act(() => fireEvent.click(compute));
    await screen.findByRole("button", { name: "Cancel" });
    expect(compute.getAttribute("aria-disabled")).toBe("true");
    expect(compute.disabled).toBe(false);
    expect(document.activeElement).toBe(compute);
    await act(async () => h.editor.cancelCompute());
    await waitFor(() => expect(compute.getAttribute("aria-disabled")).toBeNull());
  });

  it("Cancel with the keyboard focus hands it to Compute when the computation ends (it fell to the page)", async () => {
    const h = testEditor();
    await h.editor.loadScene(dilutedGas({ n: 400, packing: 0.1, seed: 2 }), { undoable: false });
    await settled(h.client);
    render(
      <EditorContext.Provider value={h.editor}>
        <CalculationPanel />
      </EditorContext.Provider>,
    );
    void h.editor.goTo(5000);
    const cancel = await screen.findByRole("button", { name: "Cancel" });
    act(() => cancel.focus());
    act(() => fireEvent.click(cancel));
    await waitFor(() => expect(screen.queryByRole("button", { name: "Cancel" })).toBeNull());
    await waitFor(() => expect(document.activeElement).toBe(screen.getByRole("button", { name: "Compute" })));
  });
});
