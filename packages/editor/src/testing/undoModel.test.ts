import { describe, expect, it } from "vitest";
import { emptyModel, made, redone, takenBack, undone } from "./undoModel";

describe("undoModel", () => {
  it("an edit made clears Redo; Undo and Redo move the last edit between the two", () => {
    const m = undone(undone(made(made(emptyModel<string>(), "x"), "y")));
    expect(m).toEqual({
      past: [],
      future: [
        { edit: "x", unchecked: false },
        { edit: "y", unchecked: false },
      ],
    });
    expect(redone(m, false)).toEqual({ past: ["x"], future: [{ edit: "y", unchecked: false }] });
    expect(made(m, "z")).toEqual({ past: ["z"], future: [] });
    expect(undone(emptyModel())).toEqual(emptyModel());
    expect(redone(emptyModel(), false)).toEqual(emptyModel());
  });

  it("an edit taken back during its check is alone in Redo, and a refusal when redone drops it", () => {
    const m = takenBack(undone(made(emptyModel<string>(), "x")), "y");
    expect(m).toEqual({ past: [], future: [{ edit: "y", unchecked: true }] });
    expect(redone(m, true)).toEqual({ past: [], future: [] });
    expect(() => redone(undone(made(emptyModel<string>(), "x")), true)).toThrow(/Redo of x refused/);
  });
});
