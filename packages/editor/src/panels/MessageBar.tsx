/**
 * The last message (a refused edit or paste, or a notice), with a close button. It sits in a slot
 * of the header one line high, whatever its length: a message that needs more lines hangs over the
 * top of the stage until it is dismissed or replaced, so showing one never moves the canvas.
 */
import { useEditor, useUi } from "../EditorContext";

export function MessageBar() {
  const editor = useEditor();
  const message = useUi((s) => s.message);
  return (
    <div className="message-slot">
      {message && (
        <div className={`message ${message.tone}`} role={message.tone === "error" ? "alert" : "status"}>
          <span>{message.text}</span>
          <button
            type="button"
            aria-label="Dismiss message"
            onClick={() => editor.ui.setState({ message: null })}
          >
            ✕
          </button>
        </div>
      )}
    </div>
  );
}
