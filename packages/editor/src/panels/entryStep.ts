/**
 * Stepping the selected log entry (Event details' Previous / Next entry): asks the worker for the
 * entry logged just before or after the selected one (protocol op `eventStep`) and makes it the
 * selected entry as clicking its row would (time, highlight, selection; playback paused). Unlike the
 * time controls' event steps (←/→, which go from one event time to the next), this walks through the
 * entries of one instant one by one (a Newton's cradle's chain). At an end of the log it says so; an
 * answer that comes after the user selected another entry is dropped.
 */
import type { Editor } from "../editor";
import { refKey } from "../remote/eventDetail";
import { highlightOf, selectionOf } from "./EventLog";

/** What is said when there is no entry to step to. */
export const NO_EARLIER = "This is the first entry of the history.";
export const NO_LATER = "This is the last entry computed so far: Next event (→) computes further.";

export async function stepEntry(editor: Editor, step: 1 | -1): Promise<void> {
  const from = editor.ui.getState().selectedEvent;
  if (from === null) return;
  try {
    const to = await editor.client.eventStep(from, step);
    if (refKey(editor.ui.getState().selectedEvent) !== refKey(from)) return;
    if (to === null) {
      editor.info(step < 0 ? NO_EARLIER : NO_LATER);
      return;
    }
    editor.ui.setState({
      t: to.detail.time,
      playing: false,
      highlight: highlightOf(to.detail),
      selection: selectionOf(to.detail),
      selectedEvent: to.ref,
    });
  } catch (e) {
    editor.ui.setState({ message: { text: e instanceof Error ? e.message : String(e), tone: "error" } });
  }
}
