/**
 * End-to-end, in Debian's Chromium: the scene view from the keyboard (reached by Tab, with a focus
 * ring and a name; arrows pan, + and − zoom, N selects the next object, Enter adds the tool's object
 * at the centre of the view, which a crosshair marks, ? lists every shortcut) while a
 * mouse click on it keeps ←/→ stepping through events; buttons that cannot act keep the focus; and
 * at 800 x 600 the time bar (Time slider, Play) is in view without scrolling, as in larger windows.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { currentTime, screenshot } from "./harness.js";
import { LOAD_NOTICE, showMessage } from "./messages.js";
import { loadPresetOn } from "./presets.js";
import { forEachWindowSize, withWindowSize } from "./windowSize.js";

const editor = editorForFile({
  afterOpen: (session) => loadPresetOn(session.page, "Bouncing balls", "ball1"),
});

type Ui = { cx: number; cy: number; scale: number; selection: { kind: string; id: string } | null };
/** The view and selection in the editor's UI store. */
function ui(): Promise<Ui> {
  return editor.page.evaluate(() => {
    type W = { chapgame: { ui: { getState(): { view: Ui; selection: Ui["selection"] } } } };
    const st = (window as unknown as W).chapgame.ui.getState();
    return { ...st.view, selection: st.selection };
  });
}

const canvas = () => editor.page.getByRole("application", { name: /^Scene view: / });

describe("the scene view from the keyboard", () => {
  it("Tab reaches the canvas, which shows a focus ring and is named by what it shows", async () => {
    // the toolbar's last control, then Tab: the canvas comes next
    await editor.page.getByRole("toolbar", { name: "Tools" }).locator("button:enabled, input").last().focus();
    await editor.page.keyboard.press("Tab");
    expect(await canvas().evaluate((el) => el === document.activeElement)).toBe(true);
    const ring = await canvas().evaluate((el) => {
      const st = getComputedStyle(el);
      return { style: st.outlineStyle, width: Number.parseFloat(st.outlineWidth) };
    });
    expect(ring.style).toBe("solid");
    expect(ring.width).toBeGreaterThanOrEqual(2);
    expect(await canvas().getAttribute("aria-describedby")).toBeTruthy();
    await screenshot(editor.page, "keyboard-canvas-focused");
  });

  it("arrows pan, + and − zoom, N selects the next body; the time does not move", async () => {
    await canvas().focus();
    const t = await currentTime(editor.page);
    const before = await ui();
    await editor.page.keyboard.press("ArrowRight");
    await poll(async () => (await ui()).cx).toBeGreaterThan(before.cx);
    await editor.page.keyboard.press("ArrowUp");
    await poll(async () => (await ui()).cy).toBeGreaterThan(before.cy);
    await editor.page.keyboard.press("+");
    await poll(async () => (await ui()).scale).toBeGreaterThan(before.scale);
    await editor.page.keyboard.press("-");
    await editor.page.keyboard.press("-");
    await poll(async () => (await ui()).scale).toBeLessThan(before.scale);
    expect(await currentTime(editor.page)).toBe(t);
    await editor.page.keyboard.press("n");
    await poll(async () => (await ui()).selection?.kind).toBe("body");
    const id = (await ui()).selection!.id;
    await poll(() => canvas().getAttribute("aria-label")).toContain(`selected: body ${id}`);
    await editor.page.keyboard.press("Escape");
    await poll(async () => (await ui()).selection).toBeNull();
  });

  it("a mouse click on the canvas does not take the focus: → then steps to the next event", async () => {
    await editor.page.getByRole("button", { name: "Fit" }).click();
    const box = (await canvas().boundingBox())!;
    await editor.page.mouse.click(box.x + 5, box.y + 5);
    expect(await canvas().evaluate((el) => el === document.activeElement)).toBe(false);
    const t = await currentTime(editor.page);
    await editor.page.keyboard.press("ArrowRight");
    await poll(() => currentTime(editor.page)).toBeGreaterThan(t);
  });

  it("? opens the list of shortcuts, Escape closes it and the focus goes back to the canvas", async () => {
    await canvas().focus();
    await editor.page.keyboard.press("n");
    await poll(async () => (await ui()).selection?.kind).toBe("body");
    const selected = (await ui()).selection;
    await editor.page.keyboard.press("?");
    const dialog = editor.page.getByRole("dialog", { name: "Keyboard shortcuts" });
    await dialog.waitFor();
    expect(await dialog.getByRole("row").count()).toBeGreaterThan(10);
    await screenshot(editor.page, "keyboard-shortcuts-dialog");
    await editor.page.keyboard.press("Delete"); // deletes nothing behind the dialog
    await editor.page.keyboard.press("Escape");
    await poll(() => dialog.count()).toBe(0);
    await editor.page.waitForTimeout(300);
    expect((await ui()).selection).toEqual(selected);
    expect(await canvas().evaluate((el) => el === document.activeElement)).toBe(true);
  });
});

describe("buttons pressed from the keyboard keep the focus", () => {
  it("the toolbar's Delete and the last Undo stay focused once they cannot act (they dropped it to the page)", async () => {
    const focused = (name: string) =>
      editor.page.evaluate((n) => document.activeElement?.textContent === n, name);
    await canvas().focus();
    await editor.page.keyboard.press("n");
    await poll(async () => (await ui()).selection?.kind).toBe("body");
    const del = editor.page
      .getByRole("toolbar", { name: "Tools" })
      .getByRole("button", { name: /^Delete: / });
    await del.focus();
    await editor.page.keyboard.press("Enter");
    await poll(async () => (await ui()).selection).toBeNull();
    expect(await focused("Delete")).toBe(true);
    const undo = editor.page.getByRole("button", { name: "Undo", exact: true });
    await undo.focus();
    for (let i = 0; i < 10 && (await undo.getAttribute("aria-disabled")) !== "true"; i++) {
      await editor.page.keyboard.press("Enter");
      await editor.page.waitForTimeout(400);
    }
    expect(await undo.getAttribute("aria-disabled")).toBe("true");
    expect(await focused("Undo")).toBe(true);
  });
});

describe("the time bar in view", () => {
  it("at 800 x 600 the Time slider and Play are in view without scrolling; larger windows keep them", async () => {
    await forEachWindowSize(
      editor.page,
      [
        [800, 600],
        [1024, 700],
        [1400, 900],
        [390, 844],
      ],
      async (width, height) => {
        await editor.page.evaluate(() => window.scrollTo(0, 0));
        for (const target of [
          editor.page.getByRole("slider", { name: "Time" }),
          editor.page.getByRole("button", { name: "Play", exact: true }),
          editor.page.getByRole("button", { name: "Next event", exact: true }),
        ]) {
          const box = (await target.boundingBox())!;
          expect(box.y, `${width} x ${height}`).toBeGreaterThanOrEqual(0);
          expect(box.y + box.height, `${width} x ${height}`).toBeLessThanOrEqual(height);
        }
        const c = (await editor.page.getByTestId("scene-canvas").boundingBox())!;
        expect(c.height, `${width} x ${height}`).toBeGreaterThanOrEqual(200);
        expect(await editor.page.evaluate(() => window.scrollY)).toBe(0);
        if (width === 800) await screenshot(editor.page, "keyboard-800x600");
      },
    );
    // a message (one after every load and undo) takes lines in a narrow header: the canvas gives
    // them up, Play stays in view
    await withWindowSize(editor.page, 800, 600, async () => {
      await showMessage(editor.page, LOAD_NOTICE, "info");
      await poll(() => editor.page.locator(".message").count()).toBe(1);
      for (const name of ["Play", "Next event"]) {
        const box = (await editor.page.getByRole("button", { name, exact: true }).boundingBox())!;
        expect(box.y + box.height, name).toBeLessThanOrEqual(600);
      }
    });
  });
});

/**
 * How blue the centre marker's right arm is on the canvas: the largest excess of blue over red of
 * the pixels from 4 to 8 CSS px right of the canvas's centre, 2 px above and below (the marker's blue
 * about 140 there; the background, the discs' outlines and the selection's orange at most 30).
 */
function centreInk(): Promise<number> {
  return canvas().evaluate((el) => {
    const c = el as HTMLCanvasElement;
    const k = c.width / c.getBoundingClientRect().width;
    const x = Math.round(c.width / 2 + 4 * k);
    const y = Math.round(c.height / 2 - 2 * k);
    const w = Math.max(1, Math.round(4 * k));
    const h = Math.max(1, Math.round(4 * k));
    const px = c.getContext("2d")!.getImageData(x, y, w, h).data;
    let most = -255;
    for (let i = 0; i < px.length; i += 4) most = Math.max(most, px[i + 2]! - px[i]!);
    return most;
  });
}

describe("adding from the keyboard", () => {
  it("focused from the keyboard with a tool that adds, the canvas marks its centre, where Enter adds; not otherwise", async () => {
    const marked = () => centreInk().then((ink) => ink > 100);
    await canvas().focus();
    // far from the balls, and Move: no marker
    for (let i = 0; i < 6; i++) await editor.page.keyboard.press("Shift+ArrowUp");
    await editor.page.keyboard.press("1");
    await editor.page.waitForTimeout(200);
    expect(await marked()).toBe(false);
    // Tab away and back: the keyboard's focus; the Disc tool then draws the marker
    await editor.page.keyboard.press("Shift+Tab");
    await editor.page.keyboard.press("Tab");
    expect(
      await canvas().evaluate((el) => el === document.activeElement && el.matches(":focus-visible")),
    ).toBe(true);
    await editor.page.keyboard.press("4");
    await poll(marked).toBe(true);
    await screenshot(editor.page, "keyboard-centre-marker");
    for (const key of ["5", "6", "7", "8"]) {
      await editor.page.keyboard.press(key);
      await poll(marked).toBe(true);
    }
    await editor.page.keyboard.press("3"); // Cue adds nothing
    await poll(marked).toBe(false);
    await editor.page.keyboard.press("4");
    await poll(marked).toBe(true);
    // the focus leaves: gone
    await editor.page.keyboard.press("Shift+Tab");
    await poll(marked).toBe(false);
    // a pointer user: the Disc tool pressed with the mouse, then a script focuses the canvas (as the
    // shortcuts dialog gives it back): no keyboard focus, no marker
    await editor.page
      .getByRole("toolbar", { name: "Tools" })
      .getByRole("button", { name: "Disc", exact: true })
      .click();
    await canvas().evaluate((el) => (el as HTMLElement).focus());
    expect(
      await canvas().evaluate((el) => el === document.activeElement && !el.matches(":focus-visible")),
    ).toBe(true);
    await editor.page.waitForTimeout(200);
    expect(await marked()).toBe(false);
    await editor.page.keyboard.press("1");
  });

  it("Enter on the focused canvas adds the tool's object at the centre of the view; a taken centre says so", async () => {
    await canvas().focus();
    // far from the balls: a free place
    for (let i = 0; i < 6; i++) await editor.page.keyboard.press("Shift+ArrowUp");
    await editor.page.keyboard.press("4");
    const before = (await ui()).selection;
    await editor.page.keyboard.press("Enter");
    await poll(async () => (await ui()).selection?.kind).toBe("body");
    const added = (await ui()).selection!;
    expect(added).not.toEqual(before);
    await poll(() =>
      editor.page
        .getByRole("status")
        .filter({ hasText: `Added disc "${added.id}"` })
        .count(),
    ).toBe(1);
    await poll(() =>
      editor.page.getByRole("table", { name: "Bodies" }).getByLabel(`${added.id} x`, { exact: true }).count(),
    ).toBe(1);
    expect(await canvas().evaluate((el) => el === document.activeElement)).toBe(true);
    // the same place again: taken by the disc just added
    await editor.page.keyboard.press("Enter");
    const alert = editor.page.getByRole("alert");
    await poll(() => alert.textContent()).toContain(`would overlap body "${added.id}"`);
    await screenshot(editor.page, "keyboard-add-at-centre");
    await editor.page.keyboard.press("Control+z");
    await poll(() =>
      editor.page.getByRole("table", { name: "Bodies" }).getByLabel(`${added.id} x`, { exact: true }).count(),
    ).toBe(0);
    await editor.page.keyboard.press("1");
  });
});
