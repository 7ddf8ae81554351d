/**
 * End-to-end helpers for the header's message bar: showing a message as the editor does (the UI
 * store's `message`, which Editor sets after a refusal, a load or an undo), and texts to show: a
 * refusal long enough to run over several lines, and the notice of a load.
 */
import type { Page } from "playwright-core";

/** A message's tone: a refusal ("error", an alert) or a notice ("info", a status). */
export type Tone = "error" | "info";

/** Shows `text` in the message bar as the editor does (null: takes the message down). */
export function showMessage(page: Page, text: string | null, tone: Tone = "error"): Promise<void> {
  return page.evaluate(
    ([t, tone]) => {
      type Ui = { ui: { setState(s: { message: { text: string; tone: Tone } | null }): void } };
      (window as unknown as { chapgame: Ui }).chapgame.ui.setState({
        message: t === null ? null : { text: t, tone },
      });
    },
    [text, tone] as const,
  );
}

/** A refusal of `sentences` sentences of 72 characters, ending in "end" (shown whole when "end" is). */
export const longRefusal = (sentences: number): string =>
  `${"A refused edit whose explanation runs over several lines of the header. ".repeat(sentences)}end`;

/** The notice of a load, as the editor shows one after every load and undo (tone "info"). */
export const LOAD_NOTICE = "Loaded the preset Bouncing balls (gravity). Undo returns to the scene you had.";
