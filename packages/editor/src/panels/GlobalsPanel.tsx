/**
 * Globals at the current time: friction g (quick buttons 1 and 9.81) and the gravity vector. The
 * cells are keyed by the scene (EditorSession.sceneSerial), as the tables' rows: a draft typed for
 * one scene's globals is dropped when a load replaces the scene, never applied to the next one's.
 */
import { useEditor, useSceneSerial } from "../EditorContext";
import { EditableCell, formatNumber, parseNumber } from "./EditableCell";
import { notANumber } from "./typedRefusal";
import { useLiveFrame } from "./useLiveFrame";

export function GlobalsPanel() {
  const editor = useEditor();
  const frame = useLiveFrame();
  const g = frame?.g ?? editor.doc.g;
  const gravity = frame?.gravity ?? editor.doc.gravity;
  const scene = useSceneSerial();
  const num = (name: string, apply: (x: number) => Promise<string | null>) => async (text: string) => {
    const x = parseNumber(text);
    return x === null ? notANumber(name, text) : apply(x);
  };
  return (
    <section className="panel" aria-labelledby="globals-title">
      <h2 id="globals-title">Globals</h2>
      <div className="row">
        g{" "}
        <EditableCell
          key={`${scene}:g`}
          label="g"
          value={formatNumber(g)}
          size={6}
          onCommit={num("g", (x) => editor.setGlobal({ g: x }))}
        />
        <button type="button" onClick={() => void editor.setGlobal({ g: 1 })}>
          g = 1
        </button>
        <button type="button" onClick={() => void editor.setGlobal({ g: 9.81 })}>
          g = 9.81
        </button>
      </div>
      <div className="row">
        gravity{" "}
        <EditableCell
          key={`${scene}:gx`}
          label="gravity x"
          value={formatNumber(gravity[0])}
          size={6}
          onCommit={num("gravity x", (x) => editor.setGlobal({ gravity: [x, gravity[1]] }))}
        />
        <EditableCell
          key={`${scene}:gy`}
          label="gravity y"
          value={formatNumber(gravity[1])}
          size={6}
          onCommit={num("gravity y", (y) => editor.setGlobal({ gravity: [gravity[0], y] }))}
        />
      </div>
    </section>
  );
}
