// @vitest-environment jsdom
// Save file: the scene's JSON saved under the name it came from (it was always scene.chapgame.json),
// through the browser's save dialog where there is one (File System Access API), else downloaded;
// the message bar says each outcome with the file's name.
import { parseScene } from "@chapgame/engine";
import { afterEach, describe, expect, it, vi } from "vitest";
import { openSceneFile } from "../doc/openScene";
import { cradleEditor, settled } from "../testing/harness";
import { loneDiscScene } from "../testing/scenes";
import { PICKER_ID, type SaveHandle, type SavePickerOptions, saveScene } from "./sceneFile";

afterEach(() => {
  vi.useRealTimers();
  vi.restoreAllMocks();
  vi.unstubAllGlobals();
});

/** A save dialog that answers with a file named `chosen` (the name suggested when undefined). */
function fakePicker(chosen?: string) {
  const asked: SavePickerOptions[] = [];
  const written: { name: string; text: string }[] = [];
  const picker = async (options: SavePickerOptions): Promise<SaveHandle> => {
    asked.push(options);
    const name = chosen ?? options.suggestedName;
    let text = "";
    return {
      name,
      createWritable: async () => ({
        write: async (data: string) => {
          text += data;
        },
        close: async () => {
          written.push({ name, text });
        },
      }),
    };
  };
  return { picker, asked, written };
}

/** Anchor clicks (downloads) recorded with the blobs they carried. */
function recordDownloads() {
  const blobs: Blob[] = [];
  const revoked: string[] = [];
  vi.stubGlobal("URL", {
    ...URL,
    createObjectURL: (b: Blob) => {
      blobs.push(b);
      return "blob:scene";
    },
    revokeObjectURL: (u: string) => revoked.push(u),
  });
  const names: string[] = [];
  vi.spyOn(HTMLAnchorElement.prototype, "click").mockImplementation(function (this: HTMLAnchorElement) {
    names.push(this.download);
  });
  return { blobs, names, revoked };
}

const message = (editor: { ui: { getState(): { message: unknown } } }) => editor.ui.getState().message;
const file = (name: string, value: unknown) =>
  new File([JSON.stringify(value)], name, { type: "application/json" });

describe("saveScene", () => {
  it("opens the save dialog with the opened file's name, writes the scene there and says so", async () => {
    const { editor, client } = await cradleEditor();
    await openSceneFile(editor, file("billiards.chapgame.json", loneDiscScene()));
    await settled(client);
    const { picker, asked, written } = fakePicker();
    await saveScene(editor, document, picker);
    expect(asked).toEqual([
      {
        suggestedName: "billiards.chapgame.json",
        id: PICKER_ID,
        types: [{ description: "chapgame scene (JSON)", accept: { "application/json": [".json"] } }],
      },
    ]);
    expect(written.map((w) => w.name)).toEqual(["billiards.chapgame.json"]);
    expect(parseScene(written[0]!.text)).toEqual(parseScene(editor.doc));
    expect(message(editor)).toEqual({ text: "Saved the scene as billiards.chapgame.json.", tone: "info" });
  });

  it("the name the user picks becomes the scene's: the next save suggests it, across edits and their undo", async () => {
    const { editor, client } = await cradleEditor();
    await openSceneFile(editor, file("billiards.chapgame.json", loneDiscScene()));
    await settled(client);
    expect(await editor.updateBody("lonely", { x: 3 })).toBeNull();
    await saveScene(editor, document, fakePicker("mine.chapgame.json").picker);
    expect(message(editor)).toEqual({ text: "Saved the scene as mine.chapgame.json.", tone: "info" });
    await editor.undo(); // the edit, made before the save: still the file saved as mine
    const next = fakePicker();
    await saveScene(editor, document, next.picker);
    expect(next.asked[0]?.suggestedName).toBe("mine.chapgame.json");
  });

  it("Undo of an opened file suggests the name of the scene before it, Redo the file's name again", async () => {
    const { editor, client } = await cradleEditor();
    await openSceneFile(editor, file("first.chapgame.json", loneDiscScene()));
    await openSceneFile(editor, file("second.chapgame.json", loneDiscScene()));
    await settled(client);
    const suggested = async () => {
      const p = fakePicker();
      await saveScene(editor, document, p.picker);
      return p.asked[0]?.suggestedName;
    };
    expect(await suggested()).toBe("second.chapgame.json");
    await editor.undo();
    expect(await suggested()).toBe("first.chapgame.json");
    await editor.undo(); // back to the cradle, loaded without a name
    expect(await suggested()).toBe("scene.chapgame.json");
    await editor.redo();
    await editor.redo();
    expect(await suggested()).toBe("second.chapgame.json");
    await editor.clear();
    expect(await suggested()).toBe("scene.chapgame.json");
  });

  it("a scene from no file is named from its title (meta.title)", async () => {
    const { editor, client } = await cradleEditor();
    await editor.loadScene({ ...loneDiscScene(), meta: { title: "Lonely Disc" } });
    await settled(client);
    const p = fakePicker();
    await saveScene(editor, document, p.picker);
    expect(p.asked[0]?.suggestedName).toBe("lonely-disc.chapgame.json");
  });

  it("a closed dialog saves nothing and says so; a file that cannot be written is an error, the scene kept", async () => {
    const { editor } = await cradleEditor();
    const downloads = recordDownloads();
    const closed = async () => {
      throw new DOMException("The user aborted a request.", "AbortError");
    };
    await saveScene(editor, document, closed);
    expect(message(editor)).toEqual({
      text: "Not saved: the save dialog was closed without saving (it suggested scene.chapgame.json).",
      tone: "info",
    });
    const locked = async (): Promise<SaveHandle> => ({
      name: "locked.json",
      createWritable: async () => {
        throw new DOMException("The file is locked.", "NoModificationAllowedError");
      },
    });
    const before = editor.doc;
    await saveScene(editor, document, locked);
    expect(message(editor)).toEqual({
      text: "Not saved: locked.json could not be written (The file is locked.). The scene is still here: save it again, in another folder or under another name.",
      tone: "error",
    });
    expect(editor.doc).toBe(before);
    const p = fakePicker();
    await saveScene(editor, document, p.picker);
    expect(p.asked[0]?.suggestedName).toBe("scene.chapgame.json"); // not renamed by a failed save
    expect(downloads.names).toEqual([]);
  });

  it("without a save dialog, or when the browser refuses it, the scene is downloaded under its name", async () => {
    const { editor, client } = await cradleEditor();
    await openSceneFile(editor, file("billiards.chapgame.json", loneDiscScene()));
    await settled(client);
    const downloads = recordDownloads();
    vi.useFakeTimers({ toFake: ["setTimeout"] }); // the object URL is revoked a second later
    await saveScene(editor, document, null);
    vi.runAllTimers();
    vi.useRealTimers();
    expect(downloads.revoked).toEqual(["blob:scene"]);
    expect(downloads.names).toEqual(["billiards.chapgame.json"]);
    expect(parseScene(await downloads.blobs[0]!.text())).toEqual(parseScene(editor.doc));
    expect(message(editor)).toEqual({
      text: "Saved the scene as billiards.chapgame.json (in the browser's downloads).",
      tone: "info",
    });
    const refused = async () => {
      throw new DOMException("Must be handling a user gesture to show a file picker.", "SecurityError");
    };
    await saveScene(editor, document, refused);
    expect(downloads.names).toEqual(["billiards.chapgame.json", "billiards.chapgame.json"]);
    expect(message(editor)).toEqual({
      text: "Saved the scene as billiards.chapgame.json (in the browser's downloads: the browser refused its save dialog: Must be handling a user gesture to show a file picker.).",
      tone: "info",
    });
  });
});

describe("Save file with a value typed in a cell and not committed", () => {
  it("says the value is not in the file, naming the cell", async () => {
    const { editor } = await cradleEditor();
    const input = document.createElement("input");
    input.setAttribute("aria-label", "c1 x");
    input.setAttribute("data-draft", "");
    document.body.append(input);
    try {
      await saveScene(editor, document, fakePicker().picker);
      expect(message(editor)).toEqual({
        text: "Saved the scene as scene.chapgame.json. The value typed in c1 x is not in it: press Enter there, then save again.",
        tone: "info",
      });
    } finally {
      input.remove();
    }
  });
});
