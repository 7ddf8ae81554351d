/**
 * End-to-end: keeping a scene author's work in Debian's Chromium. Opening a shared link never
 * loses the scene one was working on (Undo brings it back); an edit is kept by a reload that comes
 * right after it, and so is the time the tab was at (in the time field and the Event log too); a
 * link opened in the tab already open loads at once; a broken link or file says what is wrong and
 * keeps the scene; the scene Clear replaced is still what Undo brings back after a reload.
 */
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { LONELY } from "./editorScenes.js";
import { ARTIFACTS, screenshot } from "./harness.js";

const editor = editorForFile();

const bodies = () => editor.page.getByRole("table", { name: "Bodies" });
const cell = (name: string) => bodies().getByLabel(name, { exact: true });
const cellText = (name: string) =>
  cell(name).evaluate((el) => (el instanceof HTMLInputElement ? el.value : el.textContent));
const message = () => editor.page.locator(".message").textContent();

async function editCell(name: string, text: string) {
  await cell(name).click();
  const input = bodies().getByRole("textbox", { name, exact: true });
  await input.fill(text);
  await input.press("Enter");
}

async function open(url: string) {
  await editor.page.goto("about:blank");
  await editor.page.goto(url);
  await editor.page.getByRole("slider", { name: "Time" }).waitFor();
}

/** A share link's code, made the way the editor makes it (base64url of the scene's JSON). */
function shareCode(scene: unknown): string {
  return Buffer.from(JSON.stringify(scene), "utf8").toString("base64url");
}

describe("keeping work", () => {
  it("an edit survives a reload that comes right after it (autosave flushed when the page goes)", async () => {
    await poll(() => bodies().getByRole("row").count()).toBeGreaterThan(1);
    const first = (await bodies().getByRole("button", { name: / m$/ }).first().getAttribute("aria-label"))!;
    await editCell(first, "7");
    await poll(() => cellText(first)).toBe("7");
    await editor.page.reload(); // well within the autosave's 300 ms of quiet
    await editor.page.getByRole("slider", { name: "Time" }).waitFor();
    await poll(() => cellText(first)).toBe("7");
  });

  it("a reload goes back to the time the tab was at, computed again when past the horizon", async () => {
    const field = editor.page.getByRole("textbox", { name: "Time (s)" });
    const slider = editor.page.getByRole("slider", { name: "Time" });
    const horizon = Number(await slider.getAttribute("max"));
    const far = horizon + 7.5;
    await field.fill(String(far));
    await field.press("Enter");
    await poll(async () => Number(await slider.inputValue())).toBe(far);
    await editor.page.reload();
    await slider.waitFor();
    await poll(async () => Number(await slider.inputValue())).toBe(far);
    await field.fill("0");
    await field.press("Enter");
  });

  it("a reload inside the history: the time field and the Event log show the time it went back to", async () => {
    // Session 30: after a reload the slider, canvas and Bodies were at the kept t = 2.5 while
    // "t =" read 0 and the Event log marked no entry as past (the time was set while they mounted).
    const field = editor.page.getByRole("textbox", { name: "Time (s)" });
    const slider = editor.page.getByRole("slider", { name: "Time" });
    await field.fill("2.5");
    await field.press("Enter");
    await poll(async () => Number(await slider.inputValue())).toBe(2.5);
    await editor.page.reload();
    await slider.waitFor();
    await poll(async () => Number(await slider.inputValue())).toBe(2.5);
    await poll(() => field.inputValue()).toBe("2.5");
    const log = editor.page.getByRole("table", { name: "Event log" });
    // the scene's actions at t = 0 are in the past of t = 2.5
    await poll(() => log.locator("tbody tr.past").count()).toBeGreaterThan(0);
    await field.fill("0");
    await field.press("Enter");
  });

  it("Clear then a reload: Undo still brings the cleared scene back", async () => {
    const before = await bodies().getByRole("row").count();
    expect(before).toBeGreaterThan(1);
    await editor.page.getByRole("button", { name: "Clear" }).click();
    await poll(message).toMatch(/^Cleared the scene\. Undo brings it back\./);
    await poll(() => bodies().getByRole("row").count()).toBe(1);
    await editor.page.reload();
    await editor.page.getByRole("slider", { name: "Time" }).waitFor();
    await poll(() => bodies().getByRole("row").count()).toBe(1);
    await poll(message).toMatch(/^Restored the autosaved scene\. Undo brings back the scene it replaced/);
    await editor.page.getByRole("button", { name: "Undo" }).click();
    await poll(() => bodies().getByRole("row").count()).toBe(before);
  });

  it("opening a shared link keeps the scene one was working on: Undo brings it back", async () => {
    const before = await bodies().getByRole("row").count();
    await open(`${editor.session.url}#scene=${shareCode(LONELY)}`);
    await poll(() => bodies().getByRole("row").count()).toBe(2);
    expect(await cellText("lonely x")).toBe("0");
    await poll(message).toMatch(/shared/i);
    await screenshot(editor.page, "12-shared-link-opened");
    await editor.page.getByRole("button", { name: "Undo" }).click();
    await poll(() => bodies().getByRole("row").count()).toBe(before);
    await poll(() => cell("lonely x").count()).toBe(0);
  });

  it("a shared link opened in the tab already open (only the hash changes) loads at once; Undo goes back", async () => {
    const before = await bodies().getByRole("row").count();
    expect(before).not.toBe(2);
    await editor.page.evaluate((code) => {
      window.location.hash = `scene=${code}`;
    }, shareCode(LONELY));
    await poll(() => bodies().getByRole("row").count()).toBe(2);
    await poll(message).toMatch(/^Opened the shared scene/);
    await poll(() => new URL(editor.page.url()).hash).toBe("");
    await editor.page.getByRole("button", { name: "Undo" }).click();
    await poll(() => bodies().getByRole("row").count()).toBe(before);
  });

  it("after Share link a reload keeps later edits, with or without a clipboard", async () => {
    const first = (await bodies().getByRole("button", { name: / m$/ }).first().getAttribute("aria-label"))!;
    for (const [i, clipboard] of [true, false].entries()) {
      if (!clipboard)
        await editor.page.evaluate(() => {
          navigator.clipboard.writeText = () => Promise.reject(new Error("no clipboard"));
        });
      await editor.page.getByRole("button", { name: "Share link" }).click();
      await poll(message).toMatch(clipboard ? /^Link copied/ : /address bar/);
      const m = String(11 + i);
      await editCell(first, m);
      await poll(() => cellText(first)).toBe(m);
      await poll(() => new URL(editor.page.url()).hash).toBe("");
      await editor.page.reload();
      await editor.page.getByRole("slider", { name: "Time" }).waitFor();
      await poll(() => cellText(first)).toBe(m);
    }
  });

  it("a broken shared link says so in plain words, leaves the address bar, and keeps the scene", async () => {
    const before = await bodies().getByRole("row").count();
    await open(`${editor.session.url}#scene=abc%25%25`);
    await poll(message).toMatch(/^Shared link: /);
    expect(await message()).not.toMatch(/atob|Failed to execute/);
    expect(new URL(editor.page.url()).hash).toBe("");
    expect(await bodies().getByRole("row").count()).toBe(before);
  });

  it("a broken scene file: the message names the file and the field; the scene is kept", async () => {
    const before = await bodies().getByRole("row").count();
    const file = join(ARTIFACTS, "broken-field.chapgame.json");
    writeFileSync(file, JSON.stringify({ ...LONELY, actions: [{ ...LONELY.actions[0], r: "big" }] }));
    await editor.page.getByLabel("Scene file").setInputFiles(file);
    await poll(message).toMatch(
      /broken-field\.chapgame\.json: the action at t = 0 s that adds disc "lonely" \(actions\[0\]\.r\): /,
    );
    expect(await bodies().getByRole("row").count()).toBe(before);
  });
});
