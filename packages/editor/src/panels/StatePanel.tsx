/**
 * State: Copy / Paste the scene as JSON (format v1; a broken paste shows the validation message and
 * keeps the current scene), Save / Load a file (doc/openScene.ts, as a dropped file), Clear, a
 * shareable link (copied, the address bar left as it is), Undo / Redo (editorUndo.ts).
 */
import { useRef, useState } from "react";
import { openSceneFile, openSceneText } from "../doc/openScene";
import { shareLinkProblem, shareUrl } from "../doc/persistence";
import { sceneText } from "../doc/sceneIo";
import { canRedo as redoable, canUndo as undoable } from "../doc/undoIntents";
import { useEditor, useHistory } from "../EditorContext";
import { useStore } from "../store/createStore";

export function StatePanel() {
  const editor = useEditor();
  // Undo is offered as soon as an edit is asked (also while its later actions are being checked:
  // Undo then takes it back), Redo for what Undo took (doc/undoIntents.ts). An edit asked clears
  // Redo at once, also during its check (the edit is shown); one the check refuses was never made,
  // so Redo comes back with the same entries (editorUndoDuringCheck.test.ts).
  const intents = useStore(editor.intents, (s) => s);
  const canUndo = undoable(
    intents,
    useHistory((h) => h.past.length),
  );
  const canRedo = redoable(
    intents,
    useHistory((h) => h.future.length),
  );
  const [text, setText] = useState("");
  const fileRef = useRef<HTMLInputElement>(null);

  const copy = async () => {
    const json = sceneText(editor.doc);
    setText(json);
    try {
      await navigator.clipboard.writeText(json);
      editor.info("Scene copied to the clipboard.");
    } catch {
      editor.info("Scene JSON is in the text box.");
    }
  };

  const paste = async () => {
    let source = text;
    if (source.trim() === "") {
      try {
        source = await navigator.clipboard.readText();
      } catch {
        editor.ui.setState({
          message: { text: "Paste the scene JSON into the text box first.", tone: "error" },
        });
        return;
      }
    }
    await openSceneText(editor, source);
  };

  const save = () => {
    const blob = new Blob([sceneText(editor.doc)], { type: "application/json" });
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = "scene.chapgame.json";
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  };

  // The link is copied without touching the address bar: a reload then keeps later edits (a link
  // in the address bar is loaded again on reload). Without a clipboard the link is shown there, but
  // only until the next change of the scene.
  const share = async () => {
    const url = shareUrl(window.location, editor.doc);
    const problem = shareLinkProblem(url);
    if (problem !== null) {
      editor.info(problem);
      return;
    }
    try {
      await navigator.clipboard.writeText(url);
      editor.info("Link copied to the clipboard.");
    } catch {
      history.replaceState(null, "", url);
      const stop = editor.history.subscribe(() => {
        stop();
        if (window.location.href === url)
          history.replaceState(null, "", window.location.pathname + window.location.search);
      });
      editor.info("The link is in the address bar (until the next edit).");
    }
  };

  return (
    <section className="panel" aria-labelledby="state-title">
      <h2 id="state-title">State</h2>
      <div className="row">
        <button type="button" onClick={() => void editor.undo()} disabled={!canUndo}>
          Undo
        </button>
        <button type="button" onClick={() => void editor.redo()} disabled={!canRedo}>
          Redo
        </button>
        <button type="button" onClick={() => void editor.clear()}>
          Clear
        </button>
        <button type="button" onClick={save}>
          Save file
        </button>
        <button type="button" onClick={() => fileRef.current?.click()}>
          Load file
        </button>
        <input
          ref={fileRef}
          type="file"
          accept=".json,application/json"
          aria-label="Scene file"
          hidden
          onChange={async (e) => {
            const f = e.target.files?.[0];
            if (f) await openSceneFile(editor, f);
            e.target.value = "";
          }}
        />
        <button type="button" onClick={() => void share()}>
          Share link
        </button>
      </div>
      <textarea
        aria-label="Scene JSON"
        rows={4}
        value={text}
        placeholder="Scene JSON (format v1): Copy fills this box, Paste loads it"
        onChange={(e) => setText(e.target.value)}
      />
      <div className="row">
        <button type="button" onClick={() => void copy()}>
          Copy
        </button>
        <button type="button" onClick={() => void paste()}>
          Paste
        </button>
      </div>
    </section>
  );
}
