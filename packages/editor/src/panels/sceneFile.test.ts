// @vitest-environment jsdom
// Save file: the scene's JSON downloaded as scene.chapgame.json, and the message bar says so (it
// said nothing: whether a save happened was left to the browser's download bar).
import { newtonsCradle, parseScene } from "@chapgame/engine";
import { afterEach, describe, expect, it, vi } from "vitest";
import { SAVE_NAME, saveScene } from "./sceneFile";

afterEach(() => {
  vi.useRealTimers();
  vi.restoreAllMocks();
  vi.unstubAllGlobals();
});

describe("saveScene", () => {
  it("downloads the scene under its name and says so, naming the file", async () => {
    vi.useFakeTimers(); // the object URL is revoked a second later: within the test, with its stub
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
    const clicked: { download: string; href: string }[] = [];
    vi.spyOn(HTMLAnchorElement.prototype, "click").mockImplementation(function (this: HTMLAnchorElement) {
      clicked.push({ download: this.download, href: this.href });
    });
    const messages: string[] = [];
    const doc = newtonsCradle();
    saveScene({ doc, info: (t) => messages.push(t) });
    expect(clicked).toEqual([{ download: SAVE_NAME, href: "blob:scene" }]);
    vi.runAllTimers();
    expect(revoked).toEqual(["blob:scene"]);
    expect(SAVE_NAME).toBe("scene.chapgame.json");
    expect(parseScene(await (blobs[0] as Blob).text())).toEqual(parseScene(doc));
    expect(messages).toEqual(["Saved the scene as scene.chapgame.json (in the browser's downloads)."]);
  });
});
