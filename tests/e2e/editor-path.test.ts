/**
 * End-to-end: the Path view in Debian's Chromium. With a ball of the bouncing-balls preset selected,
 * ticking Path draws its whole computed path (the parabolas of its bounces, past and future) on the
 * canvas in the path colour; unticking removes it. Pixels are read from the canvas itself.
 */
import { describe, it } from "vitest";
import { editorForFile } from "./editorForFile.js";
import { screenshot, waitFor } from "./harness.js";
import { loadPresetOn } from "./presets.js";

const editor = editorForFile();

/** Canvas pixels in the orange of the path and of the selection (#d9480f, blended on the paper). */
function orangePixels(): Promise<number> {
  return editor.page.evaluate(() => {
    const c = document.querySelector<HTMLCanvasElement>("[data-testid=scene-canvas]")!;
    const d = c.getContext("2d")!.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let k = 0; k < d.length; k += 4)
      if (d[k]! > 190 && d[k + 1]! > 60 && d[k + 1]! < 160 && d[k + 2]! < 120) n++;
    return n;
  });
}

describe("the Path view", () => {
  it("draws the selected ball's whole path when ticked, and removes it when unticked", async () => {
    await loadPresetOn(editor.page, "Bouncing balls (gravity)", "ball3");
    await editor.page.getByRole("table", { name: "Bodies" }).getByLabel("ball3 x", { exact: true }).click();
    await editor.page.keyboard.press("Escape");
    await waitFor(async () =>
      editor.page.evaluate(() => {
        const ed = (window as unknown as { chapgame: { ui: { getState(): { selection: unknown } } } })
          .chapgame;
        return JSON.stringify(ed.ui.getState().selection) === JSON.stringify({ kind: "body", id: "ball3" });
      }),
    );
    await editor.page.waitForTimeout(200);
    const selectedOnly = await orangePixels();
    const path = editor.page.getByRole("checkbox", { name: "Path" });
    await path.check();
    await waitFor(async () => (await orangePixels()) > selectedOnly + 500);
    await screenshot(editor.page, "path-view");
    await path.uncheck();
    await waitFor(async () => (await orangePixels()) <= selectedOnly + 50);
  });

  it("with no body selected it says to select one", async () => {
    await editor.page.evaluate(() => {
      const ed = (window as unknown as { chapgame: { ui: { setState(s: object): void } } }).chapgame;
      ed.ui.setState({ selection: null });
    });
    await editor.page.getByRole("checkbox", { name: "Path" }).check();
    await editor.page.getByText("select a body", { exact: true }).waitFor({ timeout: 5_000 });
    await editor.page.getByRole("checkbox", { name: "Path" }).uncheck();
  });
});
