// @vitest-environment jsdom
/**
 * useHeldRows with EditableCell's onOpenChange: a row is held while any of its cells is open (a
 * refused draft stays open while another cell of the row is opened), and let go when the last one
 * closes or unmounts (its row left the table).
 */
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { openCell } from "../testing/editableCell";
import { EditableCell } from "./EditableCell";
import { type HeldRows, useHeldRows } from "./useHeldRows";

afterEach(cleanup);

function Rows({ ids, seen }: { ids: string[]; seen: { held: HeldRows["held"] } }) {
  const { held, holder } = useHeldRows();
  seen.held = held;
  return (
    <div>
      {ids.map((id) => (
        <div key={id}>
          {["x", "r"].map((f) => (
            <EditableCell
              key={f}
              label={`${id} ${f}`}
              value="1"
              onCommit={async () => `${id} ${f}: refused`}
              onOpenChange={holder(id)}
            />
          ))}
        </div>
      ))}
    </div>
  );
}

describe("useHeldRows", () => {
  it("holds a row while one of its cells is open, and lets it go when the last closes or unmounts", async () => {
    const seen = { held: new Set<string>() as HeldRows["held"] };
    const view = render(<Rows ids={["a", "b"]} seen={seen} />);
    expect([...seen.held]).toEqual([]);
    const r = openCell("a r");
    fireEvent.change(r, { target: { value: "-1" } });
    await act(async () => {
      fireEvent.keyDown(r, { key: "Enter" });
    });
    await screen.findByText("a r: refused");
    expect([...seen.held]).toEqual(["a"]);
    // a second cell of the row opened while the refused draft stays open
    const x = openCell("a x");
    expect([...seen.held]).toEqual(["a"]);
    fireEvent.keyDown(x, { key: "Escape" });
    expect([...seen.held], "the refused draft still holds the row").toEqual(["a"]);
    openCell("b x");
    expect(new Set(seen.held)).toEqual(new Set(["a", "b"]));
    fireEvent.keyDown(screen.getByRole("textbox", { name: "a r" }), { key: "Escape" });
    // (the focus back on a r's button closes b x too: it was left untyped)
    expect([...seen.held]).toEqual([]);
    openCell("b r");
    expect([...seen.held]).toEqual(["b"]);
    view.rerender(<Rows ids={["a"]} seen={seen} />);
    expect([...seen.held], "a row gone lets go").toEqual([]);
  });
});
