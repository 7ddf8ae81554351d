/**
 * The latest Frame for panels, re-rendering at most every `intervalMs` (tables show live values
 * during playback without re-rendering per animation frame). Asks for the frame of the current time
 * itself, so panels work without the canvas (and in tests). Pausing shows the latest frame at once,
 * and the next one (the paused time's) within `intervalMs`.
 */
import { useEffect, useState } from "react";
import { useEditor } from "../EditorContext";
import { motionWindow } from "../playback";
import type { Frame } from "../remote/protocol";

/** Slowest refresh while playing (ms). */
export const PLAYING_INTERVAL_MS = 500;

export function useLiveFrame(intervalMs = 150): Frame | null {
  const { client, ui } = useEditor();
  const [frame, setFrame] = useState<Frame | null>(client.latestFrame);
  useEffect(() => {
    let timer: ReturnType<typeof setTimeout> | null = null;
    let lastShown = 0;
    const show = () => {
      timer = null;
      lastShown = Date.now();
      setFrame(client.latestFrame);
    };
    const off = client.onFrame(() => {
      if (timer !== null) return;
      // While playing, tables refresh at most twice a second (their DOM is costly to repaint).
      const every = ui.getState().playing ? Math.max(intervalMs, PLAYING_INTERVAL_MS) : intervalMs;
      const wait = Math.max(0, lastShown + every - Date.now());
      timer = setTimeout(show, wait);
    });
    const want = () => {
      const s = ui.getState();
      client.wantFrame(s.t, motionWindow(s));
    };
    const offUi = ui.subscribe((s, p) => {
      // Paused: the slow playing refresh ends at once (the table showed values up to
      // PLAYING_INTERVAL_MS older than the paused time).
      if (p.playing && !s.playing) {
        if (timer !== null) clearTimeout(timer);
        lastShown = 0;
        show();
      }
      if (s.t !== p.t) want();
    });
    const offInfo = client.subscribe(want);
    want();
    return () => {
      off();
      offUi();
      offInfo();
      if (timer !== null) clearTimeout(timer);
    };
  }, [client, ui, intervalMs]);
  return frame;
}
