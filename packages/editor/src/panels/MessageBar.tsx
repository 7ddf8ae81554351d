/**
 * The last message (a refused edit or paste, or a notice), with a close button. It sits in a slot
 * of the header one line high, whatever its length, so showing, replacing or dismissing one never
 * moves the stage (its toolbar and canvas) at any window width. In a wide window a message that
 * needs more lines hangs down from the slot until it is dismissed or replaced; from 1001 px the slot
 * takes only what the header's line leaves, and where that is too narrow the message hangs under the
 * header over the top of the side column (styles/message.css: the slot once took a line of its own
 * there, empty, 37 px of canvas from 1127 to 1382 px), cut to one line there (More shows it whole),
 * in a strip the side column leaves for it under the header (useMessageStrip.ts), so that it covers
 * none of the column's panels, scrolled or not (it covered Add body, and opened whole the first
 * rows of the Bodies table, with the column scrolled to it). In a window
 * up to 1000 px wide (styles/message.css) the stage's toolbar sits right under the slot, which is
 * narrow there, so a long message is cut to its line (an ellipsis) and a More button shows it whole,
 * hanging over the stage, until Less, ✕ or the next message (MoreToggle.tsx, as a notice's); screen
 * readers read it whole either way.
 * (Below 1000 px it once took its lines in the header instead, which moved the stage down by a line
 * or more for any message longer than the slot: at 900 px a refusal of 90 characters moved the
 * canvas 6 px, a long one 51 px; at 700 px even `x: must be a number (got "abc")` did.)
 */
import { useRef } from "react";
import { useEditor, useUi } from "../EditorContext";
import { MoreToggle, useShownWhole } from "./MoreToggle";
import { useMessageStrip } from "./useMessageStrip";
import { useTextCut } from "./useTextCut";

export function MessageBar() {
  const editor = useEditor();
  const message = useUi((s) => s.message);
  /** The message shown whole (More pressed); any other message is shown on its line first. */
  const [open, toggle] = useShownWhole(message);
  const textRef = useRef<HTMLSpanElement>(null);
  const cut = useTextCut(textRef, message?.text);
  const slotRef = useRef<HTMLDivElement>(null);
  useMessageStrip(slotRef, message);
  return (
    <div className="message-slot" ref={slotRef}>
      <span className="message-hang-probe" aria-hidden="true" />
      {message && (
        <div
          className={`message ${message.tone}${open ? " open" : ""}`}
          role={message.tone === "error" ? "alert" : "status"}
        >
          <span ref={textRef}>{message.text}</span>
          <MoreToggle cut={cut} open={open} className="message-more" onToggle={toggle} />
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
