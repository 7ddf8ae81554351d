import { describe, expect, it } from "vitest";
import { dropStaleHighlight } from "./highlightGuard";
import { createUiStore } from "./uiStore";

describe("highlight guard", () => {
  it("clears the highlight when the time moves; keeps one set with the new time; ignores other changes", () => {
    const ui = createUiStore();
    dropStaleHighlight(ui);
    ui.setState({ t: 1.5, highlight: ["body:a", "body:b"] }); // an Event-log entry clicked
    expect(ui.getState().highlight).toEqual(["body:a", "body:b"]);
    ui.setState({ selection: { kind: "body", id: "a" }, speed: 2 }); // not a move of the time
    expect(ui.getState().highlight).toEqual(["body:a", "body:b"]);
    ui.setState({ t: 2.25 }); // a step, a scrub, a played frame
    expect(ui.getState()).toMatchObject({ t: 2.25, highlight: [] });
    ui.setState({ t: 3, highlight: ["line:w"] }); // another entry clicked
    expect(ui.getState().highlight).toEqual(["line:w"]);
  });
});
