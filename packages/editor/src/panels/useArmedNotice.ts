/**
 * The Event log's one polite live region for its armed ✕ buttons (RemoveActionButton): an armed
 * button shows its prompt ("Press again to remove action update body "b1" at t = 4") and hides it
 * when it disarms (a press, Escape, leaving it, the timeout, the row showing another action, the
 * button gone); hiding takes away only that button's prompt (another button armed since keeps
 * its own). A screen reader announces the prompt once, on arming; an empty region says nothing.
 * One region per log, not per row: rows are windowed and reused, and a region must exist before its
 * text changes to be announced.
 */
import { useMemo, useState } from "react";

/** What a remove button tells the log's live region. */
export interface ArmedNotice {
  show(prompt: string): void;
  hide(prompt: string): void;
}

/** The live region's text ("" when no button is armed) and the notice the buttons tell. */
export function useArmedNotice(): { text: string; notice: ArmedNotice } {
  const [text, setText] = useState("");
  const notice = useMemo<ArmedNotice>(
    () => ({
      show: (prompt) => setText(prompt),
      hide: (prompt) => setText((shown) => (shown === prompt ? "" : shown)),
    }),
    [],
  );
  return { text, notice };
}
