/**
 * End-to-end: the scene's title in Debian's Chromium. The header's Title field shows `meta.title`
 * of the scene opened; a title typed there is one undo step, saved in the file, kept by a reload
 * (autosave), and names the file Save suggests for a preset's scene (a file of the author's keeps
 * its name). The browser's save dialog is replaced by a recording stand-in, as in editor-save.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";

const editor = editorForFile();

const message = () => editor.page.locator(".message > span").textContent();
const button = (name: string) => editor.page.getByRole("button", { name, exact: true });
const title = () => editor.page.getByRole("textbox", { name: "Scene title" });

type SavePage = { asked: string[]; written: string[] };

/** Replaces the browser's save dialog by a stand-in recording the names asked and the texts written. */
async function standInDialog() {
  await editor.page.evaluate(() => {
    const w = window as unknown as SavePage & { showSaveFilePicker: unknown };
    w.asked = [];
    w.written = [];
    w.showSaveFilePicker = async (options: { suggestedName: string }) => {
      w.asked.push(options.suggestedName);
      let text = "";
      return {
        name: options.suggestedName,
        createWritable: async () => ({
          write: async (data: string) => {
            text += data;
          },
          close: async () => {
            w.written.push(text);
          },
        }),
      };
    };
  });
}

const lastSaved = () =>
  editor.page.evaluate(() => {
    const w = window as unknown as SavePage;
    return { name: w.asked.at(-1), text: w.written.at(-1) ?? "" };
  });

describe("the scene's title", () => {
  it("typed in the header, it is saved in the file and names it; Undo and Redo take it back and forth", async () => {
    // the start's preset has no title
    expect(await title().inputValue()).toBe("");
    await title().fill("Two discs, one push");
    await title().press("Enter");
    await poll(message).toBe(
      'Titled the scene "Two discs, one push": Save file suggests two-discs-one-push.chapgame.json. Undo takes it back.',
    );
    expect(await title().getAttribute("title")).toBe("Save file suggests two-discs-one-push.chapgame.json");
    await screenshot(editor.page, "scene-title");
    await standInDialog();
    await button("Save file").click();
    await poll(message).toBe("Saved the scene as two-discs-one-push.chapgame.json.");
    const file = await lastSaved();
    expect(file.name).toBe("two-discs-one-push.chapgame.json");
    expect(JSON.parse(file.text).meta).toEqual({ title: "Two discs, one push" });
    await button("Undo").click();
    await poll(message).toBe('Undone: the title set to "Two discs, one push".');
    await poll(() => title().inputValue()).toBe("");
    await button("Redo").click();
    await poll(() => title().inputValue()).toBe("Two discs, one push");
  });

  it("a reload keeps the title (autosave)", async () => {
    await editor.page.reload();
    await editor.page.getByRole("slider", { name: "Time" }).waitFor();
    await poll(() => title().inputValue()).toBe("Two discs, one push");
  });

  it("a file opened shows its title; retitled, it keeps the file's name; clicking in and out changes nothing", async () => {
    const scene = {
      format: "chapgame",
      version: 1,
      actions: [{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 }],
      meta: { title: "From disk", view: { zoom: 3 } },
    };
    await editor.page.getByLabel("Scene file").setInputFiles({
      name: "disk.chapgame.json",
      mimeType: "application/json",
      buffer: Buffer.from(JSON.stringify(scene)),
    });
    await poll(() => title().inputValue()).toBe("From disk");
    await title().click();
    await editor.page.getByRole("heading", { name: "Bodies" }).click();
    await poll(message).toBe("Opened disk.chapgame.json. Undo returns to the scene you had before.");
    await title().fill("Renamed on screen");
    await title().press("Tab");
    await poll(message).toBe(
      'Titled the scene "Renamed on screen": Save file suggests disk.chapgame.json (the scene\'s own file). Undo takes it back.',
    );
    await standInDialog();
    await editor.page.keyboard.press("Control+s");
    await poll(message).toBe("Saved the scene as disk.chapgame.json.");
    // the rest of meta is kept as it was
    expect(JSON.parse((await lastSaved()).text).meta).toEqual({
      title: "Renamed on screen",
      view: { zoom: 3 },
    });
  });
});
