/**
 * The latest Frame for panels, re-rendering at most every `intervalMs` (tables show live values
 * during playback without re-rendering per animation frame).
 */
import { useEffect, useState } from "react";
import { useEditor } from "../EditorContext";
import type { Frame } from "../remote/protocol";

export function useLiveFrame(intervalMs = 150): Frame | null {
  const { client } = useEditor();
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
      const wait = Math.max(0, lastShown + intervalMs - Date.now());
      timer = setTimeout(show, wait);
    });
    return () => {
      off();
      if (timer !== null) clearTimeout(timer);
    };
  }, [client, intervalMs]);
  return frame;
}
