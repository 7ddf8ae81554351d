/**
 * Shows when the engine (the worker) has not answered for STALL_MS and offers to restart it with
 * the same scene. A long edit in the past can legitimately take a while, so the restart is offered,
 * never forced.
 */
import { useEffect, useState } from "react";
import { useEditor } from "../EditorContext";

export const STALL_MS = 5000;

export function EngineWatch() {
  const editor = useEditor();
  const [stalled, setStalled] = useState(0);
  useEffect(() => {
    const timer = setInterval(() => setStalled(editor.client.stalledFor()), 1000);
    return () => clearInterval(timer);
  }, [editor]);
  if (stalled < STALL_MS || !editor.portFactory) return null;
  return (
    <div className="row" role="status">
      The engine has not answered for {Math.round(stalled / 1000)} s.
      <button type="button" onClick={() => void editor.restartEngine()}>
        Restart engine
      </button>
    </div>
  );
}
