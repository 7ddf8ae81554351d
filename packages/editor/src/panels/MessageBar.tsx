/** The last message (a refused edit or paste, or a notice), with a close button. */
import { useEditor, useUi } from "../EditorContext";

export function MessageBar() {
  const editor = useEditor();
  const message = useUi((s) => s.message);
  if (!message) return <div className="message empty" />;
  return (
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
  );
}
