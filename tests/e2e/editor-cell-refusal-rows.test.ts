/**
 * End-to-end, in Debian's Chromium: a refused cell never makes its row taller. The refusal is the
 * field's description drawn over the rows beside it (useCellNote.ts), so every row stays 24 px, the
 * rows below stay where they were, and the row window, which assumes rows of equal height, stays
 * right: N walks the selection through the bodies after the refused one, each row scrolled whole
 * into view. In its row the refusal made the row 50 px high, the rows below jumped 26 px and 11 of
 * 20 rows revealed after it were cut by up to 26 px at the table's foot. The refusal stays readable:
 * at the foot of the table's view it is drawn over the field (under it the box clipped it), never
 * under the sticky head, and a table of one row grows to hold it.
 */
import { describe, expect, it } from "vitest";
import { bodyGridScene, openBodyGrid } from "./bodyGridScene.js";
import { editorForFile, poll } from "./editorForFile.js";

const editor = editorForFile({
  afterOpen: ({ page }) =>
    openBodyGrid(page, bodyGridScene(40, 8, [{ time: 0, type: "addPoint", id: "p1", p: [500, 500] }])),
});

/** The table's scroll box, its rows' heights and tops by id, and the open refusal's box and side,
 *  relative to the box's view under its head (top 0) and above its foot (`view` px down). */
function tableState(table: string) {
  return editor.page.evaluate((table) => {
    const el = document.querySelector<HTMLElement>(`table[aria-label="${table}"]`)!;
    const box = el.closest<HTMLElement>(".table-scroll")!;
    const b = box.getBoundingClientRect();
    const top = b.top + box.clientTop + el.querySelector("thead")!.getBoundingClientRect().height;
    const rows: Record<string, { top: number; height: number }> = {};
    for (const tr of Array.from(el.querySelectorAll("tbody tr:not(.spacer)"))) {
      const id = tr.querySelector("td button, td input") as HTMLButtonElement | HTMLInputElement;
      const r = tr.getBoundingClientRect();
      rows[id.textContent || (id as HTMLInputElement).value] = { top: r.top - top, height: r.height };
    }
    const input = el.querySelector<HTMLInputElement>("input[aria-invalid=true]");
    const error = input ? document.getElementById(input.getAttribute("aria-describedby") ?? "") : null;
    const e = error?.getBoundingClientRect();
    return {
      scrollHeight: box.scrollHeight,
      view: b.top + box.clientTop + box.clientHeight - top,
      rows,
      refusal: e ? { text: error!.textContent, top: e.top - top, bottom: e.bottom - top } : null,
    };
  }, table);
}

/** Types `text` into the cell `label` of `table` and presses Enter; waits for its refusal. */
async function refuse(table: string, label: string, text: string): Promise<void> {
  await editor.page.getByRole("table", { name: table }).getByLabel(label, { exact: true }).click();
  await editor.page.keyboard.type(text);
  await editor.page.keyboard.press("Enter");
  await poll(async () => (await tableState(table)).refusal?.text ?? "").toContain(label);
}

function scrollBodiesTo(px: number): Promise<void> {
  return editor.page
    .locator(".table-scroll", { has: editor.page.locator("table[aria-label=Bodies]") })
    .evaluate((el, px) => {
      el.scrollTop = px;
    }, px);
}

describe("a refused cell in a table", () => {
  it("keeps its row 24 px high and the rows below in place; N then reveals each next row whole", async () => {
    await scrollBodiesTo(6 * 24);
    await poll(async () => (await tableState("Bodies")).rows.b7?.top).toBe(0);
    const before = await tableState("Bodies");
    await refuse("Bodies", "b10 r", "-1");
    const after = await tableState("Bodies");
    expect(after.refusal!.text).toContain("b10 r: must be a positive");
    expect(new Set(Object.values(after.rows).map((r) => r.height))).toEqual(new Set([24]));
    expect(after.scrollHeight).toBe(before.scrollHeight);
    for (const id of ["b11", "b12", "b13"]) expect(after.rows[id]!.top, id).toBe(before.rows[id]!.top);
    // the refusal under the field, in the view
    expect(after.refusal!.top).toBeGreaterThanOrEqual(after.rows.b10!.top + 24);
    expect(after.refusal!.bottom).toBeLessThanOrEqual(after.view);

    // N from the canvas: each next body selected, its row scrolled whole into the view
    await editor.page.getByTestId("scene-canvas").focus();
    for (let k = 11; k <= 18; k++) {
      await editor.page.keyboard.press("n");
      await poll(async () => {
        const row = (await tableState("Bodies")).rows[`b${k}`];
        const view = (await tableState("Bodies")).view;
        return row !== undefined && row.top >= -0.5 && row.top + row.height <= view + 0.5;
      }).toBe(true);
    }
    // the refused draft is still open, described by its refusal
    const field = editor.page.getByRole("table", { name: "Bodies" }).getByLabel("b10 r", { exact: true });
    expect(await field.inputValue()).toBe("-1");
    expect(await field.getAttribute("aria-invalid")).toBe("true");
  });

  it("at the foot of the view its refusal is drawn over the field, whole in the view and clear of the head", async () => {
    // b10 the last whole row in view (b3 to b10)
    await scrollBodiesTo(2 * 24);
    await poll(async () => {
      const s = await tableState("Bodies");
      return Math.round(s.view - (s.rows.b10!.top + 24));
    }).toBeLessThan(24);
    const s = await tableState("Bodies");
    expect(s.refusal, "the refusal of b10 r still shown").not.toBeNull();
    expect(s.refusal!.bottom).toBeLessThanOrEqual(s.rows.b10!.top);
    expect(s.refusal!.top).toBeGreaterThanOrEqual(0);
    await editor.page
      .getByRole("table", { name: "Bodies" })
      .getByLabel("b10 r", { exact: true })
      .press("Escape");
  });

  it("in a table of one row the table grows to hold its refusal, the row still 24 px", async () => {
    await refuse("Points", "p1 x", "zz");
    const s = await tableState("Points");
    expect(s.rows.p1!.height).toBe(24);
    expect(s.refusal!.top).toBeGreaterThanOrEqual(24);
    expect(s.refusal!.bottom).toBeLessThanOrEqual(s.view + 0.5);
    await editor.page
      .getByRole("table", { name: "Points" })
      .getByLabel("p1 x", { exact: true })
      .press("Escape");
  });
});
