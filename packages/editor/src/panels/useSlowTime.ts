/**
 * The current time for panels that need not follow every animation frame (event log, stats):
 * re-renders at most every `intervalMs`, always ending on the latest value.
 */
import { useEffect, useState } from "react";
import { useEditor } from "../EditorContext";

export function useSlowTime(intervalMs = 250): number {
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
      if (s.t === p.t || timer !== null) return;
      timer = setTimeout(show, Math.max(0, lastShown + intervalMs - Date.now()));
    });
    return () => {
      off();
      if (timer !== null) clearTimeout(timer);
    };
  }, [ui, intervalMs]);
  return t;
}
