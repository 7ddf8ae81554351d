/**
 * A persistent notice's text (NewerWorkNotice, RefusedSceneNotice), with a More button where the
 * window cuts it. In a short landscape window (styles/short.css) a notice keeps to one line over the
 * small canvas, its text cut with an ellipsis: More shows it whole (over the canvas, under the
 * toolbar) until Less or another text (MoreToggle.tsx, as the message bar's); elsewhere it wraps
 * whole and needs no More. Screen readers
 * read it whole either way. Whole, two notices once covered all but 54 to 69 px of the canvas at
 * 844 x 390 and 700 x 420.
 */
import { useRef } from "react";
import { MoreToggle, useShownWhole } from "./MoreToggle";
import { useTextCut } from "./useTextCut";

export function NoticeText({ text }: { text: string }) {
  const ref = useRef<HTMLSpanElement>(null);
  /** The text shown whole (More pressed); another text is shown on its line first. */
  const [open, toggle] = useShownWhole(text);
  const cut = useTextCut(ref, text);
  return (
    <>
      <span ref={ref} className={open ? "notice-text open" : "notice-text"}>
        {text}
      </span>
      <MoreToggle cut={cut} open={open} className="notice-more" onToggle={toggle} />
    </>
  );
}
