/**
 * Where a table cell's note (its refusal, or "checking the later actions…") is drawn: over the rows
 * next to the cell's field, out of the table's layout, so that a refusal never makes its row taller
 * (the row window, useRowWindow.tsx, assumes rows of equal height). Contract: `placeCellNote` takes
 * the field's box, the table's view (its scroll box's client area under the sticky head) and the
 * note's size, all in the same coordinates (CSS px, the window's), and returns the note's top-left
 * corner in them: under the field when it fits in the view, else over it when that fits, else under
 * it with `growBy` px the view must grow at its foot to hold it (a table of few rows). The note
 * keeps inside the view sideways (it starts at the field's left edge, moved left as far as needed).
 * `shown` is false when the field is out of the view (scrolled away): its note would float over
 * other rows or the head. Pure: no DOM (useCellNote.ts measures and applies).
 */

/** An axis-aligned box (CSS px). */
export interface Box {
  top: number;
  bottom: number;
  left: number;
  right: number;
}

export interface NotePlace {
  top: number;
  left: number;
  /** Drawn over the field (its last rows in view had no room under it). */
  above: boolean;
  /** Px the view lacks under the field to hold the note when it fits on neither side (else 0). */
  growBy: number;
  /** Whether the field is in the view: a note for a field scrolled away is not drawn. */
  shown: boolean;
}

/** Space between the field and its note (px): the note reads as the field's, not the next row's. */
export const NOTE_GAP_PX = 2;

export function placeCellNote(field: Box, view: Box, note: { width: number; height: number }): NotePlace {
  const need = note.height + NOTE_GAP_PX;
  const roomBelow = view.bottom - field.bottom;
  const roomAbove = field.top - view.top;
  const middle = (field.top + field.bottom) / 2;
  const shown = middle >= view.top && middle <= view.bottom;
  const above = roomBelow < need && roomAbove >= need;
  const growBy = shown && !above && roomBelow < need ? need - Math.max(0, roomBelow) : 0;
  const left = Math.max(view.left, Math.min(field.left, view.right - note.width));
  return {
    top: above ? field.top - need : field.bottom + NOTE_GAP_PX,
    left,
    above,
    growBy,
    shown,
  };
}
