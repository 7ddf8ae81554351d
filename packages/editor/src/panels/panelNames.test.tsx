// @vitest-environment jsdom
/**
 * Accessible names and hints of the panels: the Bodies, Lines and Points headings are their titles
 * alone (their Add button beside them, not inside: the heading read "Bodies (6) Add body"); the
 * "0" button is "0: go to start" with the tooltip "Go to start"; each Event log entry is described by what
 * activating it does.
 */
import { cleanup, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { cradleEditor } from "../testing/harness";
import { BodiesTable } from "./BodiesTable";
import { CalculationPanel } from "./CalculationPanel";
import { EventLog, ROW_HINT } from "./EventLog";
import { LinesTable } from "./LinesTable";
import { PointsTable } from "./PointsTable";
import { StatePanel } from "./StatePanel";
import { TimePanel } from "./TimePanel";

afterEach(cleanup);

async function renderPanels() {
  const h = await cradleEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <BodiesTable />
      <LinesTable />
      <PointsTable />
      <TimePanel />
      <EventLog />
    </EditorContext.Provider>,
  );
  return h;
}

describe("panel names", () => {
  it("the Bodies, Lines and Points headings are their titles; their Add buttons are not in them", async () => {
    await renderPanels();
    await waitFor(() => expect(screen.getByRole("heading", { name: "Bodies (6)" })).toBeTruthy());
    for (const [title, add] of [
      ["Bodies (6)", "Add body"],
      ["Lines (0)", "Add line"],
      ["Points (0)", "Add point"],
    ] as const) {
      const heading = screen.getByRole("heading", { name: title });
      const button = screen.getByRole("button", { name: add });
      expect(heading.contains(button), add).toBe(false);
      // beside it, in the same head of the panel
      expect(button.parentElement, add).toBe(heading.parentElement);
    }
  });

  it('the "0" button is named "0: go to start" (its visible text first) with the tooltip "Go to start"', async () => {
    await renderPanels();
    const button = screen.getByRole("button", { name: "0: go to start" });
    expect(button.textContent).toBe("0");
    expect(button.title).toBe("Go to start");
  });

  it("each Event log entry is described by what activating it does; its name is its text", async () => {
    await renderPanels();
    const log = screen.getByRole("table", { name: "Event log" });
    await waitFor(() => expect(within(log).getAllByText("striker").length).toBeGreaterThan(0));
    const rows = within(log)
      .getAllByRole("row")
      .filter((r) => r.querySelector("td") !== null);
    expect(rows.length).toBeGreaterThan(0);
    for (const row of rows) {
      const hint = document.getElementById(row.getAttribute("aria-describedby") ?? "");
      expect(hint?.textContent).toBe(ROW_HINT);
      expect(row.getAttribute("aria-label")).toBeNull();
    }
    expect(ROW_HINT).toMatch(/Enter.*go to this event/);
  });

  it('the State panel\'s button that empties the scene says so: "Clear scene" (a plain "Clear" beside the text box read as clearing the box)', async () => {
    const h = await cradleEditor();
    render(
      <EditorContext.Provider value={h.editor}>
        <StatePanel />
      </EditorContext.Provider>,
    );
    const clear = screen.getByRole("button", { name: "Clear scene" });
    expect(clear.title).toBe("Remove every body, line, point and action (Undo brings them back)");
    expect(screen.queryByRole("button", { name: "Clear" })).toBeNull();
    expect(h.editor.doc.actions.length).toBeGreaterThan(0);
    clear.click();
    await waitFor(() => expect(h.editor.doc.actions).toEqual([]));
  });

  it("Compute and Auto-extend say in their tooltips what they compute", async () => {
    const h = await cradleEditor();
    render(
      <EditorContext.Provider value={h.editor}>
        <CalculationPanel />
      </EditorContext.Provider>,
    );
    expect(screen.getByRole("button", { name: "Compute" }).title).toMatch(
      /^Compute further past the horizon/,
    );
    const auto = screen.getByRole("checkbox", { name: "Auto-extend" });
    expect(auto.closest("label")?.title).toMatch(/^While playing forwards, compute further by itself/);
  });
});
