/**
 * Keeps the canvas highlight (the participants of a clicked Event-log entry) tied to the time it was
 * set at: once the current time moves away (stepping, scrubbing, playing, typing a time), the
 * highlight is cleared, so the canvas does not light the participants of an event the time has left.
 * A store update that moves the time and sets a new highlight (clicking another entry) keeps the new
 * highlight.
 */
import type { UiStore } from "./uiStore";

/** Clears the highlight of `ui` whenever the time changes without it; returns the unsubscribe. */
export function dropStaleHighlight(ui: UiStore): () => void {
  return ui.subscribe((s, prev) => {
    if (s.t !== prev.t && s.highlight === prev.highlight && s.highlight.length > 0)
      ui.setState({ highlight: [] });
  });
}
