import { describe, expect, it } from "vitest";
import { askedTogether, emptyModel, made, type Outcome, redone, takenBack, undone } from "./undoModel";

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

  it("edits asked together: Undos bound to them, the last first; only the last can be taken back", () => {
    const base = made(emptyModel<string>(), "w");
    const never = () => false;
    /** Edits x then y asked together, with what became of each. */
    const xy = (x: Outcome, y: Outcome): [string, Outcome][] => [
      ["x", x],
      ["y", y],
    ];
    const checked = (edit: string) => ({ edit, unchecked: false });
    expect(askedTogether(base, xy("made", "made"), 2, 0, never)).toEqual({
      past: ["w"],
      future: [checked("x"), checked("y")],
    });
    expect(askedTogether(base, xy("made", "takenBack"), 2, 0, never)).toEqual({
      past: ["w"],
      future: [checked("x"), { edit: "y", unchecked: true }],
    });
    // y, brought back by the second Redo, is refused by its check.
    expect(askedTogether(base, xy("made", "takenBack"), 2, 2, () => true)).toEqual({
      past: ["w", "x"],
      future: [],
    });
    // A refused edit's Undo does nothing, nor does the Redo bound to it; Undos past the edits undo w.
    expect(askedTogether(base, xy("refused", "made"), 3, 1, never)).toEqual({
      past: ["w"],
      future: [checked("y")],
    });
    expect(askedTogether(base, xy("made", "refused"), 2, 2, never)).toEqual({ past: ["w", "x"], future: [] });
    expect(() => askedTogether(base, xy("takenBack", "made"), 2, 0, never)).toThrow(
      /x taken back though an edit was asked after it/,
    );
    expect(() => askedTogether(base, [["x", "takenBack"]], 0, 0, never)).toThrow(/no Undo was/);
  });
});
