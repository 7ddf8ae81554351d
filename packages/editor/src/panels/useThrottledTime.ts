/**
 * The current time for text and panels that need not follow every animation frame: re-renders at
 * most every `intervalMs`, always ending on the latest value (a number changing 60 times a second is
 * unreadable, and re-rendering a panel per animation frame is what the editor avoids).
 * - useShownTime (the Time panel's "t =" field): exact and at once while paused (steps, scrubbing,
 *   typed times), throttled only while playing.
 * - useSlowTime (event log, stats): always throttled.
 * Both start from the time at their subscription, not only at their first render (a time set in
 * between notified nobody: a reload's kept time read 0 in the field and the Event log).
 */
import { useEffect, useState } from "react";
import { useEditor } from "../EditorContext";

function useThrottledTime(intervalMs: number, exactWhilePaused: boolean): number {
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
      if (exactWhilePaused && !s.playing) {
        if (timer !== null) clearTimeout(timer);
        show();
        return;
      }
      if (s.t === p.t || timer !== null) return;
      timer = setTimeout(show, Math.max(0, lastShown + intervalMs - Date.now()));
    });
    // A time set between the first render and this subscription (a reloaded tab going back to its
    // time while the app mounts, timeKeep.ts) notified nobody: show it now.
    show();
    return () => {
      off();
      if (timer !== null) clearTimeout(timer);
    };
  }, [ui, intervalMs, exactWhilePaused]);
  return t;
}

export function useShownTime(playingIntervalMs = 100): number {
  return useThrottledTime(playingIntervalMs, true);
}

export function useSlowTime(intervalMs = 250): number {
  return useThrottledTime(intervalMs, false);
}
