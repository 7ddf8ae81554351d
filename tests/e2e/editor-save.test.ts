/**
 * End-to-end: saving a scene and adding objects, as a scene author does it in Debian's Chromium.
 * Save file suggests the name the scene came from (the file opened, the name picked at the last
 * save, a preset's) in the browser's save dialog (the File System Access API, replaced here by a
 * recording stand-in: headless Chromium closes the real dialog at once), downloads the scene under
 * that name where the browser has no such dialog, and says in the message bar what was saved under
 * which name; a reload keeps the name (autosave); a value typed in a cell and not committed is said
 * not to be in the file. The Add body / Add line / Add point buttons say what they added where, or why they
 * added nothing.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";

const editor = editorForFile();

const message = () => editor.page.locator(".message > span").textContent();
const button = (name: string) => editor.page.getByRole("button", { name, exact: true });

const BILLIARDS = {
  format: "chapgame",
  version: 1,
  g: 9.81,
  gravity: [0, 0],
  actions: [
    { time: 0, type: "addBody", id: "cue", x: 0, y: 0, r: 1, m: 1, v: [3, 0] },
    { time: 0, type: "addBody", id: "red", x: 10, y: 0, r: 1, m: 1 },
  ],
};

type SavePage = {
  /** The names the stand-in dialog was opened with, and the files it wrote. */
  asked: string[];
  written: { name: string; text: string }[];
  /** The name the "user" picks in the dialog (the suggested one when null). */
  pick: string | null;
};

/** Replaces the browser's save dialog by a stand-in that records what it is asked and written. */
async function standInDialog() {
  await editor.page.evaluate(() => {
    const w = window as unknown as SavePage & { showSaveFilePicker: unknown };
    w.asked = [];
    w.written = [];
    w.pick = null;
    w.showSaveFilePicker = async (options: { suggestedName: string }) => {
      w.asked.push(options.suggestedName);
      const name = w.pick ?? options.suggestedName;
      let text = "";
      return {
        name,
        createWritable: async () => ({
          write: async (data: string) => {
            text += data;
          },
          close: async () => {
            w.written.push({ name, text });
          },
        }),
      };
    };
  });
}

const saved = () =>
  editor.page.evaluate(() => {
    const w = window as unknown as SavePage;
    return { asked: w.asked, written: w.written.map((f) => f.name), text: w.written.at(-1)?.text ?? "" };
  });

async function openFile(name: string, scene: unknown) {
  await editor.page.getByLabel("Scene file").setInputFiles({
    name,
    mimeType: "application/json",
    buffer: Buffer.from(JSON.stringify(scene)),
  });
  await poll(message).toBe(`Opened ${name}. Undo returns to the scene you had before.`);
}

describe("Save file", () => {
  it("suggests the opened file's name, then the name picked; Undo of the open goes back to the name before", async () => {
    await standInDialog();
    await openFile("billiards.chapgame.json", BILLIARDS);
    await button("Save file").click();
    await poll(message).toBe("Saved the scene as billiards.chapgame.json.");
    const first = await saved();
    expect(first.asked).toEqual(["billiards.chapgame.json"]);
    expect(JSON.parse(first.text)).toMatchObject({ format: "chapgame", actions: BILLIARDS.actions });
    // the user names it otherwise in the dialog: Ctrl+S then suggests that name
    await editor.page.evaluate(() => {
      (window as unknown as SavePage).pick = "break-shot.chapgame.json";
    });
    await button("Save file").click();
    await poll(message).toBe("Saved the scene as break-shot.chapgame.json.");
    await editor.page.evaluate(() => {
      (window as unknown as SavePage).pick = null;
    });
    await editor.page.keyboard.press("Control+s");
    await poll(message).toBe("Saved the scene as break-shot.chapgame.json.");
    expect((await saved()).asked.at(-1)).toBe("break-shot.chapgame.json");
    await screenshot(editor.page, "save-named");
    // Undo of the open: the scene before it is the start's preset, saved under the preset's name
    await button("Undo").click();
    await poll(message).toMatch(/^Undone: the scene loaded over yours/);
    await button("Save file").click();
    await poll(message).toBe("Saved the scene as original-demo.chapgame.json.");
  });

  it("a reload keeps the name the scene came from", async () => {
    await openFile("billiards.chapgame.json", BILLIARDS);
    await editor.page.reload();
    await editor.page.getByRole("table", { name: "Bodies" }).getByLabel("red x", { exact: true }).waitFor();
    await standInDialog();
    await button("Save file").click();
    await poll(message).toBe("Saved the scene as billiards.chapgame.json.");
  });

  it("Ctrl+S in a cell with a value typed says that value is not in the file", async () => {
    const bodies = editor.page.getByRole("table", { name: "Bodies" });
    await bodies.getByLabel("red x", { exact: true }).click();
    const input = bodies.getByRole("textbox", { name: "red x", exact: true });
    await input.fill("12");
    await editor.page.keyboard.press("Control+s");
    await poll(message).toBe(
      "Saved the scene as billiards.chapgame.json. The value typed in red x is not in it: press Enter there, then save again.",
    );
    const written = await saved();
    expect(JSON.parse(written.text).actions[1]).toMatchObject({ id: "red", x: 10 });
    await input.press("Escape");
  });

  it("downloads the scene under its name where the browser has no save dialog", async () => {
    await openFile("billiards.chapgame.json", BILLIARDS);
    await editor.page.evaluate(() => {
      (window as unknown as { showSaveFilePicker: unknown }).showSaveFilePicker = undefined;
    });
    const [download] = await Promise.all([editor.page.waitForEvent("download"), button("Save file").click()]);
    expect(download.suggestedFilename()).toBe("billiards.chapgame.json");
    await poll(message).toBe("Saved the scene as billiards.chapgame.json (in the browser's downloads).");
  });
});

describe("Add buttons", () => {
  it("say what they added and where; with no room, why nothing was added", async () => {
    await button("Clear scene").click();
    await poll(message).toBe("Cleared the scene. Undo brings it back.");
    await button("Add body").click();
    await poll(message).toMatch(/^Added disc "b1" at \(-?[\d.]+, -?[\d.]+\), radius [\d.]+\.$/);
    await button("Add line").click();
    await poll(message).toMatch(
      /^Added segment "l1" from \(-?[\d.]+, -?[\d.]+\) to \(-?[\d.]+, -?[\d.]+\)\.$/,
    );
    await button("Add point").click();
    await poll(message).toMatch(/^Added point "p1" at \(-?[\d.]+, -?[\d.]+\)\.$/);
    await screenshot(editor.page, "add-buttons");
    // the view inside one huge disc: no free place near the centre
    await editor.page.evaluate(async () => {
      const ed = (window as unknown as { chapgame: { loadScene(s: unknown): Promise<string | null> } })
        .chapgame;
      await ed.loadScene({
        format: "chapgame",
        version: 1,
        actions: [{ time: 0, type: "addBody", id: "big", x: 0, y: 0, r: 1e6, m: 1 }],
      });
    });
    await editor.page.getByRole("table", { name: "Bodies" }).getByLabel("big x", { exact: true }).waitFor();
    await editor.page.evaluate(() => {
      const ed = (window as unknown as { chapgame: { ui: { setState(p: object): void } } }).chapgame;
      ed.ui.setState({ view: { cx: 0, cy: 0, scale: 20 } });
    });
    await button("Add body").click();
    await poll(message).toBe(
      'Add body: nothing added: no free place for a new disc of radius 1 within 100 of the centre of the view (0, 0) (body "big" is there). Zoom out or pan to an emptier part of the scene, then press Add body again.',
    );
    expect(await editor.page.locator(".message").getAttribute("role")).toBe("alert");
  });
});
