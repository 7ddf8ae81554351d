/**
 * The current time for a text display: exact and at once while paused (steps, scrubbing, typed
 * times), at most every `playingIntervalMs` while playing (a number changing 60 times a second is
 * unreadable, and re-rendering its panel per animation frame is what the editor avoids).
 */
import { useEffect, useState } from "react";
import { useEditor } from "../EditorContext";

export function useShownTime(playingIntervalMs = 100): number {
  const { ui } = useEditor();
  const [t, setT] = useState(ui.getState().t);
  useEffect(() => {
    let timer: ReturnType<typeof setTimeout> | null = null;
    let lastShown = 0;
    const show = () => {
      timer = null;
      lastShown = Date.now();
      setT(ui.getState().t);
    };
    const off = ui.subscribe((s, p) => {
      if (s.t === p.t && s.playing === p.playing) return;
      if (!s.playing) {
        if (timer !== null) clearTimeout(timer);
        show();
        return;
      }
      if (timer !== null) return;
      timer = setTimeout(show, Math.max(0, lastShown + playingIntervalMs - Date.now()));
    });
    return () => {
      off();
      if (timer !== null) clearTimeout(timer);
    };
  }, [ui, playingIntervalMs]);
  return t;
}
