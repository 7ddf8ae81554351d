/**
 * Dropping a scene file anywhere on the page opens it the way Load file does (doc/openScene.ts).
 * While files are dragged over the page a drop indicator covers it. Only drags that carry files are
 * taken: text dragged into the Scene JSON box drops there as before. Several files, or a file that
 * is not JSON, are refused with a message and the scene is kept.
 */
import { useEffect, useState } from "react";
import { droppedSceneFile, openSceneFile } from "../doc/openScene";
import { useEditor } from "../EditorContext";

/**
 * Milliseconds without a dragover after which the indicator goes: browsers repeat dragover while a
 * drag stays over the page, still or not (HTML's drag-and-drop model: every 350 ms ± 200 ms).
 */
const STALE_MS = 1000;

const carriesFiles = (e: DragEvent) => e.dataTransfer?.types.includes("Files") ?? false;

export function FileDrop() {
  const editor = useEditor();
  const [over, setOver] = useState(false);

  useEffect(() => {
    // dragenter and dragleave come in pairs for every element crossed: count them. dragover repeats
    // while files are over the page; when it stops (a drag cancelled or left
    // without a dragleave the page saw), the indicator goes after STALE_MS.
    let depth = 0;
    let stale: ReturnType<typeof setTimeout> | null = null;
    const hideLater = () => {
      if (stale !== null) clearTimeout(stale);
      stale = setTimeout(() => {
        depth = 0;
        setOver(false);
      }, STALE_MS);
    };
    const onEnter = (e: DragEvent) => {
      if (!carriesFiles(e)) return;
      depth++;
      setOver(true);
      hideLater();
    };
    const onLeave = (e: DragEvent) => {
      if (!carriesFiles(e)) return;
      depth = Math.max(depth - 1, 0);
      if (depth === 0) setOver(false);
    };
    const onOver = (e: DragEvent) => {
      if (!carriesFiles(e)) return;
      e.preventDefault(); // allows the drop (the browser would open the file in place of the editor)
      if (e.dataTransfer) e.dataTransfer.dropEffect = "copy";
      setOver(true);
      hideLater();
    };
    const onDrop = (e: DragEvent) => {
      if (!carriesFiles(e)) return;
      e.preventDefault();
      depth = 0;
      setOver(false);
      const file = droppedSceneFile(e.dataTransfer?.files ?? []);
      if (typeof file === "string") editor.ui.setState({ message: { text: file, tone: "error" } });
      else void openSceneFile(editor, file);
    };
    window.addEventListener("dragenter", onEnter);
    window.addEventListener("dragleave", onLeave);
    window.addEventListener("dragover", onOver);
    window.addEventListener("drop", onDrop);
    return () => {
      if (stale !== null) clearTimeout(stale);
      window.removeEventListener("dragenter", onEnter);
      window.removeEventListener("dragleave", onLeave);
      window.removeEventListener("dragover", onOver);
      window.removeEventListener("drop", onDrop);
    };
  }, [editor]);

  if (!over) return null;
  return (
    <div className="file-drop" role="status" aria-label="Drop indicator">
      <span>Drop a scene file (.json) to open it</span>
    </div>
  );
}
