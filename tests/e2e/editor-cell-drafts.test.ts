/**
 * End-to-end, in Debian's Chromium: a table cell's draft survives any scroll of its table. The Bodies
 * table renders only the rows in view (useRowWindow.tsx), and a row scrolled more than OVERSCAN rows
 * out of the view was unmounted with its open cell: a refused draft (r = -1) and its refusal were
 * gone when the row came back. The row of an open cell is now always rendered (useHeldRows.ts), its
 * refusal hidden while it is out of view and shown again when it returns; a key typed into its
 * field (which keeps the focus out of view) scrolls its row back into view. A draft never reaches
 * another object: deleting its body drops it (Undo brings the body back, not the draft), and so
 * does a load that replaces the scene, even one whose bodies have the same ids; the message of the
 * delete or the load says which draft was dropped.
 */
import { describe, expect, it } from "vitest";
import { bodyGridScene, openBodyGrid } from "./bodyGridScene.js";
import { editorForFile, poll } from "./editorForFile.js";

/** The editor's methods these tests call (boot.ts puts the editor on window.chapgame). */
type Chapgame = {
  ui: { setState(patch: object): void; getState(): { message: { text: string } | null } };
  deleteSelection(): Promise<string | null>;
  undo(): Promise<void>;
  loadScene(scene: unknown): Promise<string | null>;
};
type PageWindow = { chapgame: Chapgame };

const SCENE = bodyGridScene(48, 8);
const editor = editorForFile({ afterOpen: ({ page }) => openBodyGrid(page, SCENE) });

const bodies = () => editor.page.getByRole("table", { name: "Bodies" });
const cell = (label: string) => bodies().getByLabel(label, { exact: true });

/** The message bar's text. */
const message = () =>
  editor.page.evaluate(() => (window as unknown as PageWindow).chapgame.ui.getState().message?.text ?? "");

/** Scrolls the Bodies table's box to `px` and waits until the row of `visible` is rendered. */
async function scrollBodiesTo(px: number, visible: string): Promise<void> {
  await editor.page
    .locator(".table-scroll", { has: editor.page.locator("table[aria-label=Bodies]") })
    .evaluate((el, px) => {
      el.scrollTop = px;
    }, px);
  await poll(() => cell(`${visible} x`).count()).toBe(1);
}

/** The refusal describing the field `label`, as the reader sees it: its text and whether it is drawn. */
function refusalOf(label: string) {
  return bodies().evaluate((table, label) => {
    const input = table.querySelector<HTMLInputElement>(`input[aria-label="${label}"]`);
    if (!input) return null;
    const note = document.getElementById(input.getAttribute("aria-describedby") ?? "");
    if (!note) return { value: input.value, text: null, drawn: false };
    const shown = getComputedStyle(note.closest<HTMLElement>(".cell-note") ?? note).visibility !== "hidden";
    return { value: input.value, text: note.textContent, drawn: shown };
  }, label);
}

/** Whether the field `label` is whole in its scroll box's view, below the box's sticky header. */
function fieldInView(label: string): Promise<boolean> {
  return bodies().evaluate((table, label) => {
    const input = table.querySelector<HTMLInputElement>(`input[aria-label="${label}"]`);
    const box = table.closest<HTMLElement>(".table-scroll");
    if (!input || !box) return false;
    const f = input.getBoundingClientRect();
    const b = box.getBoundingClientRect();
    const head = table.querySelector("thead")?.getBoundingClientRect().height ?? 0;
    return f.top >= b.top + head && f.bottom <= b.top + box.clientHeight;
  }, label);
}

/** From the top of the table, refuses `text` typed in the cell `label`. */
async function refuse(label: string, text: string): Promise<void> {
  await scrollBodiesTo(0, "b1");
  await cell(label).click();
  await editor.page.keyboard.type(text);
  await editor.page.keyboard.press("Enter");
  await poll(async () => (await refusalOf(label))?.text ?? "").toContain(`${label}: must be a positive`);
}

describe("a refused draft in the Bodies table", () => {
  it("survives a scroll far out of the row window and back, its refusal shown again", async () => {
    await refuse("b3 r", "-1");
    // the last rows: b3 is 40 rows, ten times OVERSCAN, out of the view
    await scrollBodiesTo(48 * 24, "b48");
    expect(await refusalOf("b3 r"), "kept while out of view, its refusal not drawn over other rows").toEqual({
      value: "-1",
      text: expect.stringContaining("b3 r: must be a positive"),
      drawn: false,
    });
    await scrollBodiesTo(0, "b1");
    await poll(() => refusalOf("b3 r")).toEqual({
      value: "-1",
      text: expect.stringContaining("b3 r: must be a positive"),
      drawn: true,
    });
    expect(await cell("b3 r").getAttribute("aria-invalid")).toBe("true");
    // the draft is still the user's to correct: Enter applies the corrected value
    await cell("b3 r").fill("4");
    await cell("b3 r").press("Enter");
    await poll(() => cell("b3 r").textContent()).toBe("4");
  });

  it("brings its row back into view when a key is typed into it out of view (the keys went to a field the author could not see)", async () => {
    await refuse("b4 r", "-1");
    await scrollBodiesTo(48 * 24, "b48");
    expect(await editor.page.evaluate(() => document.activeElement?.getAttribute("aria-label"))).toBe("b4 r");
    expect(await fieldInView("b4 r"), "scrolled out of view, the focus kept").toBe(false);
    await editor.page.keyboard.press("Backspace");
    await editor.page.keyboard.type("2");
    await poll(() => fieldInView("b4 r")).toBe(true);
    await poll(() => refusalOf("b4 r")).toEqual({
      value: "-2",
      text: expect.stringContaining("b4 r: must be a positive"),
      drawn: true,
    });
    await cell("b4 r").press("Escape");
    await poll(() => cell("b4 r").textContent()).toBe("3");
  });

  it("is dropped with its body when the body is deleted out of view; Undo brings the body back, not the draft", async () => {
    await refuse("b5 r", "-1");
    await scrollBodiesTo(48 * 24, "b48");
    await editor.page.evaluate(async () => {
      const w = window as unknown as PageWindow;
      w.chapgame.ui.setState({ selection: { kind: "body", id: "b5" } });
      await w.chapgame.deleteSelection();
    });
    // the typed value did not vanish without a word
    expect(await message()).toBe(
      'Deleted body "b5" at t = 0 s (Undo brings it back). Dropped the draft b5 r = -1, typed and not applied.',
    );
    await scrollBodiesTo(0, "b1");
    await poll(() => cell("b5 x").count()).toBe(0);
    await editor.page.evaluate(() => (window as unknown as PageWindow).chapgame.undo());
    await poll(() => cell("b5 r").textContent()).toBe("3");
    expect(await bodies().locator("input").count(), "no cell open").toBe(0);
  });

  it("is dropped when a load replaces the scene, even by one with the same ids", async () => {
    await refuse("b6 r", "-1");
    await scrollBodiesTo(48 * 24, "b48");
    await editor.page.evaluate((scene) => (window as unknown as PageWindow).chapgame.loadScene(scene), SCENE);
    expect(await message()).toBe("Dropped the draft b6 r = -1, typed and not applied.");
    await scrollBodiesTo(0, "b1");
    await poll(() => cell("b6 r").textContent()).toBe("3");
    expect(await bodies().locator("input").count(), "no cell open").toBe(0);
  });

  it("is dropped when a load replaces the scene while it is in view", async () => {
    await refuse("b2 r", "-1");
    await editor.page.evaluate((scene) => (window as unknown as PageWindow).chapgame.loadScene(scene), SCENE);
    await poll(() => bodies().locator("input").count()).toBe(0);
    expect(await cell("b2 r").textContent()).toBe("3");
  });
});
