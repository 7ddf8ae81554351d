// @vitest-environment jsdom
import { act, cleanup, render } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { EditorContext } from "../EditorContext";
import { cradleEditor } from "../testing/harness";
import { StageNotices } from "./StageNotices";

/** jsdom lays nothing out: the notices' list is 30.4 px high a notice, and its resize observer
 *  is called by the test (as the browser calls it when a notice comes, goes or wraps). */
const observers: (() => void)[] = [];

afterEach(() => {
  cleanup();
  vi.unstubAllGlobals();
  vi.restoreAllMocks();
  observers.length = 0;
});

async function setup() {
  vi.stubGlobal(
    "ResizeObserver",
    class {
      constructor(private readonly cb: () => void) {}
      observe() {
        observers.push(this.cb);
      }
      disconnect() {}
    },
  );
  vi.spyOn(HTMLElement.prototype, "getBoundingClientRect").mockImplementation(function (this: HTMLElement) {
    const height = this.classList.contains("stage-notices") ? 30.4 * this.children.length : 0;
    return { height } as DOMRect;
  });
  const h = await cradleEditor();
  const view = render(
    <EditorContext.Provider value={h.editor}>
      <StageNotices />
    </EditorContext.Provider>,
  );
  return { ...h, view };
}

const resized = () =>
  act(() => {
    for (const cb of observers) cb();
  });

describe("the persistent notices' cover", () => {
  it("is the height of the notices shown (whole pixels, up), 0 with none and once unmounted", async () => {
    const { editor, view } = await setup();
    expect(editor.ui.getState().noticesCover).toBe(0);
    act(() => editor.ui.setState({ newerWork: { tab: "other", savedAt: Date.UTC(2026, 0, 1, 12) } }));
    resized();
    expect(editor.ui.getState().noticesCover).toBe(31);
    act(() => editor.ui.setState({ refusedScene: { reason: "r: must be a number", text: "{}", tab: null } }));
    resized();
    expect(editor.ui.getState().noticesCover).toBe(61);
    act(() => editor.ui.setState({ newerWork: null, refusedScene: null }));
    resized();
    expect(editor.ui.getState().noticesCover).toBe(0);
    act(() => editor.ui.setState({ newerWork: { tab: "other", savedAt: Date.UTC(2026, 0, 1, 12) } }));
    resized();
    view.unmount();
    expect(editor.ui.getState().noticesCover).toBe(0);
  });
});
