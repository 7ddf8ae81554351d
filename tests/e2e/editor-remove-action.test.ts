/**
 * End-to-end: the Event log's remove button (RemoveActionButton) with a real mouse and keyboard in
 * Debian's Chromium, at a wide window. Armed, it once grew into "Remove?", the table re-laid out and
 * moved it from under the pointer; Chromium then reported the pointer leaving and that disarmed it,
 * so a mouse could never remove at widths of 1280 px and more (audit of session 16). A held Enter
 * (its auto-repeat) removed. jsdom has no layout and no key repeat: these are checked here.
 */
import type { Locator } from "playwright-core";
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

const editor = editorForFile({ width: 1400, height: 900 });

/** The scene's number of actions (the editor is window.chapgame). */
const actionCount = () =>
  editor.page.evaluate(
    () => (window as unknown as { chapgame: { doc: { actions: unknown[] } } }).chapgame.doc.actions.length,
  );

/** Waits until the worker computes nothing and the Event log has read the scene as it is now. */
async function settled() {
  await editor.page.waitForFunction(
    () => {
      type Info = { computing: unknown; revision: number };
      const ed = (window as unknown as { chapgame: { client: { getSnapshot(): Info } } }).chapgame;
      const i = ed.client.getSnapshot();
      return i.computing === null && i.revision > 0;
    },
    undefined,
    { timeout: 15_000, polling: 50 },
  );
  await sleep(400); // the log reads a page at most every 250 ms
}

/** The ✕ of the Event log's last action entry (the default scene's log lists its actions first). */
async function lastRemove(): Promise<Locator> {
  await settled();
  const buttons = editor.page.getByRole("table", { name: "Event log" }).locator("button.log-remove");
  await poll(() => buttons.count()).toBeGreaterThan(0);
  const b = buttons.last();
  await b.scrollIntoViewIfNeeded();
  return b;
}

describe("Event log remove button", () => {
  it("a mouse removes with two clicks at a wide window: armed, the button stays under the pointer", async () => {
    const before = await actionCount();
    const button = await lastRemove();
    const rest = (await button.boundingBox())!;
    const x = rest.x + rest.width / 2;
    const y = rest.y + rest.height / 2;
    await editor.page.mouse.move(x, y);
    await editor.page.mouse.click(x, y);
    await poll(() => button.getAttribute("aria-label")).toMatch(/^Confirm: remove action/);
    expect(await button.boundingBox()).toEqual(rest); // same size and place
    await screenshot(editor.page, "12-remove-armed-1400");
    await sleep(600); // past the confirm delay; the pointer's leaving would have disarmed it by now
    expect(await button.getAttribute("aria-label")).toMatch(/^Confirm: remove action/);
    await editor.page.mouse.click(x, y);
    await poll(actionCount).toBe(before - 1);
    await editor.page.keyboard.press("Control+z");
    await poll(actionCount).toBe(before);
  });

  it("a held Enter only arms it (its repeats never press it)", async () => {
    const before = await actionCount();
    await editor.page.mouse.move(0, 0); // the pointer's leaving plays no part
    const button = await lastRemove();
    await button.focus();
    await editor.page.keyboard.down("Enter");
    await sleep(500);
    for (let i = 0; i < 10; i++) {
      await editor.page.keyboard.down("Enter"); // a key already down: Playwright sends it as a repeat
      await sleep(33);
    }
    await editor.page.keyboard.up("Enter");
    await sleep(300);
    expect(await actionCount()).toBe(before);
    expect(await button.getAttribute("aria-label")).toMatch(/^Confirm: remove action/);
    await editor.page.keyboard.press("Escape");
  });
});
