/**
 * editorForFile in Debian's Chromium: the file's session is open for its tests (afterOpen run once,
 * before them, with that session), a describe block's own session is another window of its own size
 * and is closed when the block ends, and the handle read when there is no session says why.
 */
import type { BrowserContext } from "playwright-core";
import { describe, expect, it } from "vitest";
import { editorForFile, poll, type SharedEditor } from "./editorForFile.js";
import type { Session } from "./harness.js";

/** The error `read` throws, or null when it throws none. */
function errorOf(read: () => unknown): Error | null {
  try {
    read();
    return null;
  } catch (e) {
    return e as Error;
  }
}

const openedWith: Session[] = [];
const editor = editorForFile({
  afterOpen: (session) => {
    openedWith.push(session);
  },
});
/** Read while the file is collected, before any beforeAll ran. */
const readTooEarly = errorOf(() => editor.page);

const windowSize = (e: SharedEditor) => e.page.evaluate(() => [window.innerWidth, window.innerHeight]);

it("read while the file is collected, the handle says its beforeAll has not opened the editor yet", () => {
  expect(readTooEarly?.message).toBe(
    "editorForFile: no editor page to read: the beforeAll of editorForFile has not opened it yet: read it inside a test or a hook, not while the file is collected",
  );
});

it("in a test, the page is the open editor's, and afterOpen ran once with that session", async () => {
  expect(openedWith).toHaveLength(1);
  expect(openedWith[0]).toBe(editor.session);
  expect(editor.page).toBe(editor.session.page);
  expect(editor.page.url()).toBe(editor.session.url);
  await editor.page.getByRole("slider", { name: "Time" }).waitFor();
  expect(await windowSize(editor)).toEqual([1400, 900]);
});

let ownContext: BrowserContext | undefined;
let ownClosed = false;
let ownEditor: SharedEditor | undefined;

describe("a describe block's own session", () => {
  const small = editorForFile({ width: 800, height: 600 });
  ownEditor = small;

  it("is another editor, in a window of its size, open beside the file's", async () => {
    expect(small.session).not.toBe(editor.session);
    expect(small.session.url).not.toBe(editor.session.url);
    expect(await windowSize(small)).toEqual([800, 600]);
    expect(await windowSize(editor)).toEqual([1400, 900]);
    await poll(() => small.page.getByRole("slider", { name: "Time" }).count()).toBe(1);
    ownContext = small.session.context;
    ownContext.on("close", () => {
      ownClosed = true;
    });
  });
});

it("is closed when its describe block ends, and its handle then says so; the file's stays open", async () => {
  expect(ownContext).toBeDefined();
  expect(ownClosed).toBe(true);
  expect(errorOf(() => ownEditor!.session)?.message).toBe(
    "editorForFile: no editor session to read: the afterAll of editorForFile has closed it",
  );
  expect(await editor.page.getByRole("slider", { name: "Time" }).count()).toBe(1);
});
