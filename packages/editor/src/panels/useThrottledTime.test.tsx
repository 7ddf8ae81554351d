// @vitest-environment jsdom
// The Time panel's field (useShownTime) and the Event log and Stats (useSlowTime) show the store's
// time, also when it moved between their first render and their subscription: at start, a reloaded
// tab goes back to its time (timeKeep.ts) while the app mounts.
import { act, cleanup, render, screen } from "@testing-library/react";
import { useLayoutEffect } from "react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext, useEditor } from "../EditorContext";
import type { Editor } from "../editor";
import { createUiStore } from "../store/uiStore";
import { useShownTime, useSlowTime } from "./useThrottledTime";

afterEach(cleanup);

function Shown() {
  return <span data-testid="shown">{useShownTime()}</span>;
}

function Slow() {
  return <span data-testid="slow">{useSlowTime()}</span>;
}

/** Moves the time once mounted, before the passive effects of the components beside it run. */
function MovesTime({ to }: { to: number }) {
  const { ui } = useEditor();
  useLayoutEffect(() => ui.setState({ t: to }), [ui, to]);
  return null;
}

describe("useShownTime and useSlowTime", () => {
  it("show a time set after their first render and before they subscribed (a reload's kept time)", async () => {
    // Session 30: a reload went back to t = 3.5 (slider, canvas, Bodies) while "t =" read 0 and the
    // Event log marked no entry as past, until the time moved again.
    const editor = { ui: createUiStore() } as unknown as Editor;
    render(
      <EditorContext.Provider value={editor}>
        <Shown />
        <Slow />
        <MovesTime to={3.5} />
      </EditorContext.Provider>,
    );
    expect(editor.ui.getState().t).toBe(3.5);
    await act(() => new Promise((r) => setTimeout(r, 300)));
    expect(screen.getByTestId("shown").textContent).toBe("3.5");
    expect(screen.getByTestId("slow").textContent).toBe("3.5");
  });
});
