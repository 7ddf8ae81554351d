/**
 * The editor session the end-to-end tests share, and their patient `poll`. Contract:
 * `editorForFile(options)` registers, in the scope it is called in (a test file's top level, or a
 * describe block for a session of its own), a beforeAll that opens the built editor (openEditor, at
 * the given window size) and then runs `afterOpen`, and an afterAll that closes it. It returns a
 * handle whose `session` and `page` getters give that live session and its page; read before the
 * beforeAll opened it (while the file is collected), after it failed, or after the afterAll closed
 * it, they throw an error that says which. Called twice, it gives two independent sessions.
 */
import type { Page } from "playwright-core";
import { afterAll, beforeAll, expect } from "vitest";
import { openEditor, type Session } from "./harness.js";

/** How long `poll` waits for its expectation: patient enough for a loaded machine (shared, 2 cores). */
export const POLL_TIMEOUT_MS = 15_000;
/** How often `poll` asks again: the editor's panels refresh a few times a second. */
export const POLL_INTERVAL_MS = 50;

/** Polls like expect.poll, patient enough for a loaded machine. */
export function poll<T>(fn: () => T | Promise<T>): ReturnType<typeof expect.poll<T | Promise<T>>> {
  return expect.poll(fn, { timeout: POLL_TIMEOUT_MS, interval: POLL_INTERVAL_MS });
}

export interface EditorForFileOptions {
  /** The window's width in CSS px (openEditor's 1400 when left out). */
  width?: number;
  /** The window's height in CSS px (openEditor's 900 when left out). */
  height?: number;
  /** The beforeAll's timeout in ms, afterOpen included (vitest's hookTimeout when left out). */
  openTimeoutMs?: number;
  /**
   * More set-up in the same beforeAll, once the editor shows its start scene (loading a preset,
   * replacing a browser dialog by a stand-in). The session is closed by the afterAll even when
   * this throws.
   */
  afterOpen?: (session: Session) => void | Promise<void>;
}

/** The live session of an editorForFile; each getter throws until the beforeAll has opened it. */
export interface SharedEditor {
  readonly session: Session;
  readonly page: Page;
}

/** Where a handle's session is when there is none to read. */
type NotOpen = "not opened yet" | "opening failed" | "closed";

/** What reading the handle means in each of those, for the error it throws. */
const NOT_OPEN: Record<NotOpen, string> = {
  "not opened yet":
    "the beforeAll of editorForFile has not opened it yet: read it inside a test or a hook, not while the file is collected",
  "opening failed": "the beforeAll of editorForFile failed to open it (its error is reported with the hook)",
  closed: "the afterAll of editorForFile has closed it",
};

/** Opens the editor for the tests of the calling scope (file or describe); see the header. */
export function editorForFile(options: EditorForFileOptions = {}): SharedEditor {
  const { afterOpen, openTimeoutMs, ...windowSize } = options;
  let state: Session | NotOpen = "not opened yet";

  beforeAll(async () => {
    state = "opening failed";
    const session = await openEditor(windowSize);
    state = session;
    await afterOpen?.(session);
  }, openTimeoutMs);

  afterAll(async () => {
    const closing = state;
    state = "closed";
    if (typeof closing !== "string") await closing.close();
  });

  const live = (what: "session" | "page"): Session => {
    if (typeof state !== "string") return state;
    throw new Error(`editorForFile: no editor ${what} to read: ${NOT_OPEN[state]}`);
  };
  return {
    get session() {
      return live("session");
    },
    get page() {
      return live("page").page;
    },
  };
}
