/**
 * State: Copy / Paste the scene as JSON (format v1; a broken paste shows the validation message,
 * "Pasted text: " before it, and keeps the current scene, doc/openScene.ts's openPastedText; a
 * paste is one undo step, and says so), Clear scene (named so: a plain "Clear" beside the text box
 * read as clearing the box), a shareable link (copied, the address bar
 * left as it is). Undo, Redo, Save file and Load file are in the header
 * (SceneActions.tsx).
 */
import { useState } from "react";
import { openPastedText } from "../doc/openScene";
import { shareLinkProblem, shareUrl } from "../doc/persistence";
import { sceneText } from "../doc/sceneIo";
import { useEditor } from "../EditorContext";

export function StatePanel() {
  const editor = useEditor();
  const [text, setText] = useState("");

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
    await openPastedText(editor, source);
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
        <button
          type="button"
          title="Remove every body, line, point and action (Undo brings them back)"
          onClick={() => void editor.clear()}
        >
          Clear scene
        </button>
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
