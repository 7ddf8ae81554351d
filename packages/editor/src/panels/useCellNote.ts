/**
 * Keeps a table cell's note (its refusal, or "checking the later actions…") where placeCellNote
 * (cellNotePlace.ts) puts it: drawn over the rows under the cell's field, or over those above it at
 * the foot of the table's view, never in the row (a refusal made its row 26 px taller, and the row
 * window, the scroll to a selected row and N / Shift+N, which assume rows of equal height, were off
 * by that much). Contract: while `active` (the note is rendered), the element `note` (absolutely
 * positioned by styles/tables.css inside a table's scroll box) is moved beside `field` on every
 * render, on the scroll box's scroll and on a resize of the box or the note; hidden (visibility,
 * still the field's description) while the field is scrolled out of the view; a table too short to
 * hold it on either side grows at its foot by what is missing (min-height), its rows unchanged,
 * until the note goes. The note's containing block is the panel (`contain: content`), not the
 * scroll box, so the box never clips it nor scrolls further for it. A cell outside a table's scroll
 * box (the Globals panel) is left alone: its note stays in the flow under the field.
 */
import { type RefObject, useLayoutEffect, useRef } from "react";
import { placeCellNote } from "./cellNotePlace";

export function useCellNote(
  field: RefObject<HTMLElement | null>,
  note: RefObject<HTMLElement | null>,
  active: boolean,
): void {
  const place = useRef<() => void>(() => {});

  useLayoutEffect(() => {
    const f = field.current;
    const n = note.current;
    const box = f?.closest<HTMLElement>(".table-scroll");
    if (!active || !f || !n || !box) return;
    /** The note's offsets last written (its style's top and left, px from its containing block). */
    let written = { top: 0, left: 0 };
    /** Px the box was grown by (min-height) to hold the note, and its height before. */
    let grown = 0;
    let natural = 0;
    const update = () => {
      const b = box.getBoundingClientRect();
      if (!(b.height > 0)) return; // nothing laid out (jsdom, a hidden panel)
      const head = box.querySelector("thead")?.getBoundingClientRect().height ?? 0;
      const top = b.top + box.clientTop;
      const left = b.left + box.clientLeft;
      // the view as the table's rows alone make it (without the growth this note asked for)
      const view = {
        top: top + head,
        bottom: top + box.clientHeight - grown,
        left,
        right: left + box.clientWidth,
      };
      const r = n.getBoundingClientRect();
      const p = placeCellNote(f.getBoundingClientRect(), view, { width: r.width, height: r.height });
      // the containing block's corner, from where the note is now and the offsets that put it there
      written = { top: p.top - (r.top - written.top), left: p.left - (r.left - written.left) };
      n.style.top = `${written.top}px`;
      n.style.left = `${written.left}px`;
      n.style.visibility = p.shown ? "" : "hidden";
      n.dataset.side = p.above ? "above" : "below";
      if (p.growBy !== grown) {
        if (grown === 0) natural = box.offsetHeight;
        grown = p.growBy;
        box.style.minHeight = grown > 0 ? `${natural + grown}px` : "";
      }
    };
    place.current = update;
    update();
    box.addEventListener("scroll", update, { passive: true });
    const ro = typeof ResizeObserver === "undefined" ? null : new ResizeObserver(update);
    ro?.observe(box);
    ro?.observe(n);
    return () => {
      place.current = () => {};
      box.removeEventListener("scroll", update);
      ro?.disconnect();
      if (grown > 0) box.style.minHeight = "";
    };
  }, [field, note, active]);

  // (no dependencies: the row's values, and so the columns' widths, may change on any render)
  useLayoutEffect(() => place.current());
}
