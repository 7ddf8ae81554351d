/**
 * The Path view's note: "select a body" while Path is ticked and no body is selected, or where the
 * path of the selected body was cut ("drawn up to t = … s (too long to draw whole)"); nothing
 * otherwise. It hangs over the top of the canvas at its right, under the toolbar and any persistent
 * notice (StageNotices.tsx renders it after their list; styles/notices.css), and lets the pointer
 * through to the canvas. Beside Path on the toolbar it took the toolbar's width: from 901 to
 * 1280 px it wrapped the toolbar onto a second line while it showed (57 px high, not 33: 24 px of
 * canvas). It is not one of the notices Fit leaves out (a fitted view does not move when Path is
 * ticked). Its box is a live region, always there, so a screen reader says the note as it comes.
 */
import { useUi } from "../EditorContext";
import { formatNumber } from "./EditableCell";

export function PathNote() {
  const path = useUi((s) => s.path);
  const bodySelected = useUi((s) => s.selection?.kind === "body");
  const cutAt = useUi((s) => s.pathShown?.cutAt ?? null);
  const note = !path
    ? null
    : !bodySelected
      ? "select a body"
      : cutAt !== null
        ? `drawn up to t = ${formatNumber(cutAt)} s (too long to draw whole)`
        : null;
  return (
    <p className="path-note" role="status">
      {note !== null && <small>{note}</small>}
    </p>
  );
}
