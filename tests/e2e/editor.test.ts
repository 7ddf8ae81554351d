/**
 * End-to-end: the built editor in Debian's Chromium, driven by accessible names like a user.
 * Scenes come from the engine's presets; expected times are exact consequences of the preset
 * (Newton's cradle: the striker at x = −6 moves at 4 towards c1 at x = 0, both r = 1, so the first
 * collision is at t = (6 − 2) / 4 = 1).
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { currentTime, screenshot, scrubTo, waitFor } from "./harness.js";

const editor = editorForFile();

const bodies = () => editor.page.getByRole("table", { name: "Bodies" });
/** A Bodies cell by its accessible name ("striker vx"): a button at rest, an input while edited. */
const cell = (name: string) => bodies().getByLabel(name, { exact: true });
const cellValue = async (name: string) =>
  Number(await cell(name).evaluate((el) => (el instanceof HTMLInputElement ? el.value : el.textContent)));

async function loadPreset(title: RegExp | string) {
  const select = editor.page.getByRole("combobox", { name: "Preset" });
  const value = await select.locator("option", { hasText: title }).first().getAttribute("value");
  await select.selectOption(value!);
  await editor.page.getByRole("button", { name: "Load preset" }).click();
  await waitFor(async () => (await currentTime(editor.page)) === 0);
}

async function editCell(name: string, text: string) {
  await cell(name).click();
  const input = bodies().getByRole("textbox", { name, exact: true });
  await input.fill(text);
  await input.press("Enter");
}

describe("editor end to end", () => {
  it("starts with the default scene and loads a preset", async () => {
    await poll(() => bodies().getByRole("row").count()).toBeGreaterThan(1);
    await screenshot(editor.page, "01-default-scene");
    await loadPreset("Newton's cradle");
    await poll(() => bodies().getByRole("row").count()).toBe(7);
    expect(await cellValue("striker x")).toBe(-6);
    expect(await cellValue("c5 x")).toBe(8);
    await screenshot(editor.page, "02-newtons-cradle");
  });

  it("plays and pauses", async () => {
    await editor.page.getByRole("button", { name: "Play", exact: true }).click();
    await waitFor(async () => (await currentTime(editor.page)) > 0.3);
    await editor.page.getByRole("button", { name: "Pause", exact: true }).click();
    const t = await currentTime(editor.page);
    await editor.page.waitForTimeout(300);
    expect(await currentTime(editor.page)).toBe(t);
    await screenshot(editor.page, "03-paused");
  });

  it("scrubs to a time and shows the exact state there", async () => {
    await scrubTo(editor.page, 0.5);
    expect(await currentTime(editor.page)).toBe(0.5);
    await poll(() => cellValue("striker x")).toBe(-4);
  });

  it("steps to the next and previous event", async () => {
    await scrubTo(editor.page, 0);
    await editor.page.getByRole("button", { name: "Next event" }).click();
    await poll(() => currentTime(editor.page)).toBe(1);
    await poll(() => cellValue("striker vx")).toBe(0);
    await editor.page.getByRole("button", { name: "Previous event" }).click();
    await poll(() => currentTime(editor.page)).toBe(0);
    await poll(() => cellValue("striker vx")).toBe(4);
    await editor.page.keyboard.press("ArrowRight");
    await poll(() => currentTime(editor.page)).toBe(1);
    await screenshot(editor.page, "04-first-collision");
  });

  it("replays backwards with the Reverse button", async () => {
    await scrubTo(editor.page, 2);
    await editor.page.getByRole("button", { name: "−1×: play backwards" }).click();
    await waitFor(async () => (await currentTime(editor.page)) < 1.7);
    const t1 = await currentTime(editor.page);
    await editor.page.waitForTimeout(200);
    const t2 = await currentTime(editor.page);
    expect(t2).toBeLessThan(t1);
    await editor.page.getByRole("button", { name: "Pause", exact: true }).click();
    expect(await editor.page.getByRole("textbox", { name: "Speed", exact: true }).inputValue()).toBe("-1");
  });

  it("edits a body in the table; a refused value shows the message in place and changes nothing", async () => {
    await scrubTo(editor.page, 0);
    await editCell("striker vx", "8");
    await poll(() => cellValue("striker vx")).toBe(8);
    // The cell reads 8 while the edit is still on its way; a step that starts before the edit lands
    // is dropped (the scene changed while it waited), so wait for the edit's confirmation first.
    await editor.page.getByRole("status").filter({ hasText: "velocity to (8," }).waitFor();
    await editor.page.getByRole("button", { name: "Next event" }).click();
    await poll(() => currentTime(editor.page)).toBe(0.5);
    await scrubTo(editor.page, 0);
    await editCell("c3 r", "-1");
    // announced once, by the message bar; shown in place as the input's description
    await poll(() => editor.page.getByRole("alert").allTextContents()).toEqual([
      "c3 r: must be a positive finite number (got -1)✕",
    ]);
    await poll(() => bodies().locator(".cell-error").textContent()).toBe(
      "c3 r: must be a positive finite number (got -1)",
    );
    await screenshot(editor.page, "05-refused-cell");
    await cell("c3 r").press("Escape");
    expect(await cellValue("c3 r")).toBe(1);
  });

  it("undoes the edit with Ctrl+Z and redoes it with Ctrl+Shift+Z", async () => {
    await editor.page.getByRole("slider", { name: "Time" }).focus();
    await editor.page.locator("body").click({ position: { x: 5, y: 5 } });
    await editor.page.keyboard.press("Control+z");
    await poll(() => cellValue("striker vx")).toBe(4);
    await editor.page.keyboard.press("Control+Shift+z");
    await poll(() => cellValue("striker vx")).toBe(8);
    await editor.page.getByRole("button", { name: "Undo" }).click();
    await poll(() => cellValue("striker vx")).toBe(4);
  });

  it("Ctrl+Z, Ctrl+Shift+Z and space work with the Time slider focused (it kept them from the editor)", async () => {
    await loadPreset("Newton's cradle");
    const speed = editor.page.getByRole("textbox", { name: "Speed" });
    await speed.fill("1"); // forwards (an earlier test replayed backwards)
    await speed.press("Enter");
    await editCell("striker vx", "8");
    await poll(() => cellValue("striker vx")).toBe(8);
    await editor.page.getByRole("button", { name: "Undo" }).click();
    await poll(() => cellValue("striker vx")).toBe(4);
    const slider = editor.page.getByRole("slider", { name: "Time" });
    await scrubTo(editor.page, 0.25);
    expect(await slider.evaluate((el) => el === document.activeElement)).toBe(true);
    await editor.page.keyboard.press("Control+Shift+z");
    await poll(() => cellValue("striker vx")).toBe(8);
    await editor.page.keyboard.press("Control+z");
    await poll(() => cellValue("striker vx")).toBe(4);
    await editor.page.keyboard.press("Space");
    await waitFor(async () => (await currentTime(editor.page)) > 0.5);
    await editor.page.keyboard.press("Space");
    await poll(() => editor.page.getByRole("button", { name: "Play", exact: true }).count()).toBe(1);
    await scrubTo(editor.page, 0);
    // The table refreshes a few times a second: wait until it shows t = 0, so that the next test
    // starts from a settled state (it read the striker at t = 0.25 otherwise, now and then).
    await poll(() => cellValue("striker x")).toBe(-6);
  });

  it("a broken paste shows the validation message and keeps the scene", async () => {
    const broken = JSON.stringify({
      format: "chapgame",
      version: 1,
      actions: [{ time: 0, type: "addBody", id: "x", x: 0, y: 0, r: -2, m: 1 }],
    });
    await editor.page.getByRole("textbox", { name: "Scene JSON" }).fill(broken);
    await editor.page.getByRole("button", { name: "Paste", exact: true }).click();
    await poll(() => editor.page.getByRole("alert").first().textContent()).toContain("actions[0].r");
    expect(await cellValue("striker x")).toBe(-6);
    expect(await bodies().getByRole("row").count()).toBe(7);
    await screenshot(editor.page, "06-broken-paste");
  });

  it("keeps the scene across a reload (autosave)", async () => {
    await scrubTo(editor.page, 0);
    await editCell("c1 m", "3");
    await poll(() => cellValue("c1 m")).toBe(3);
    await editor.page.waitForTimeout(600);
    await editor.page.reload();
    await editor.page.getByRole("slider", { name: "Time" }).waitFor();
    await poll(() => cellValue("c1 m")).toBe(3);
    expect(await cellValue("striker x")).toBe(-6);
    await screenshot(editor.page, "07-after-reload");
  });

  it("adds a disc with the Disc tool, moves it by dragging, and deletes it with the Delete key", async () => {
    await loadPreset("Bouncing balls");
    await poll(() => bodies().getByRole("row").count()).toBe(7);
    const canvas = editor.page.getByTestId("scene-canvas");
    const box = (await canvas.boundingBox())!;
    await editor.page.getByRole("button", { name: "Disc", exact: true }).click();
    await canvas.click({ position: { x: box.width * 0.5, y: 40 } });
    await poll(() => bodies().getByRole("row").count()).toBe(8);
    const y0 = await cellValue("b1 y");
    await editor.page.getByRole("button", { name: "Move", exact: true }).click();
    await editor.page.mouse.move(box.x + box.width * 0.5, box.y + 40);
    await editor.page.mouse.down();
    await editor.page.mouse.move(box.x + box.width * 0.5, box.y + 90, { steps: 5 });
    await editor.page.mouse.up();
    await poll(() => cellValue("b1 y")).toBeLessThan(y0);
    await editor.page.getByRole("checkbox", { name: "Trails" }).check();
    await editor.page.getByRole("button", { name: "Play", exact: true }).click();
    await waitFor(async () => (await currentTime(editor.page)) > 1);
    await editor.page.getByRole("button", { name: "Pause", exact: true }).click();
    await screenshot(editor.page, "09-bouncing-balls-trails");
    await scrubTo(editor.page, 0);
    await editor.page.locator("body").click({ position: { x: 5, y: 5 } });
    await canvas.click({ position: { x: box.width * 0.5, y: 90 } });
    await editor.page.keyboard.press("Delete");
    await poll(() => bodies().getByRole("row").count()).toBe(7);
  });

  it("Galperin's billiard with 3 digits, computed until idle, counts 314 collisions", async () => {
    await editor.page.getByRole("button", { name: "∞: compute until no event is left" }).click();
    const select = editor.page.getByRole("combobox", { name: "Preset" });
    await select.selectOption("galperin");
    await editor.page.getByRole("spinbutton", { name: "Digits of π" }).fill("3");
    await editor.page.getByRole("button", { name: "Load preset" }).click();
    const stats = editor.page.getByRole("table", { name: "Stats" });
    const stat = async (name: string) =>
      Number(await stats.getByRole("row").filter({ hasText: name }).getByRole("cell").textContent());
    await poll(async () => (await stat("body–body")) + (await stat("body–line"))).toBe(314);
    await poll(() => editor.page.getByText("(no more events)").count()).toBe(1);
    await screenshot(editor.page, "10-galperin-314");
    // (its own name: the Time slider is the only control called "Time")
    await editor.page.getByRole("checkbox", { name: "Limit by time" }).check();
    expect(await editor.page.getByRole("checkbox", { name: "Time", exact: true }).count()).toBe(0);
  });

  it("space plays and pauses; the event log jumps to an event", async () => {
    await loadPreset("Newton's cradle");
    await editor.page.locator("body").click({ position: { x: 5, y: 5 } });
    await editor.page.keyboard.press("Space");
    await waitFor(async () => (await currentTime(editor.page)) > 0.2);
    await editor.page.keyboard.press("Space");
    const log = editor.page.getByRole("table", { name: "Event log" });
    const row = log.getByRole("row").filter({ hasText: "body–body" }).first();
    await row.click();
    await poll(() => currentTime(editor.page)).toBe(1);
    await screenshot(editor.page, "08-event-log-jump");
  });
});
