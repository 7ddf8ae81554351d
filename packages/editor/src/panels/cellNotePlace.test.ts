import { describe, expect, it } from "vitest";
import { NOTE_GAP_PX, placeCellNote } from "./cellNotePlace";

/** A table's view under its head: 196 px high (220 less a 24 px head), 400 px wide. */
const VIEW = { top: 124, bottom: 320, left: 10, right: 410 };
/** A field of a row of 24 px whose top is `top`, 60 px wide from x = 100. */
const fieldAt = (top: number, left = 100) => ({ top, bottom: top + 24, left, right: left + 60 });
const NOTE = { width: 200, height: 30 };

describe("placeCellNote", () => {
  it("draws the note under the field when it fits in the view under it", () => {
    const p = placeCellNote(fieldAt(124), VIEW, NOTE);
    expect(p).toEqual({ top: 148 + NOTE_GAP_PX, left: 100, above: false, growBy: 0, shown: true });
  });

  it("draws it over the field at the foot of the view, where under it the box would clip it", () => {
    // the last whole row: 296..320, nothing under it in view
    const p = placeCellNote(fieldAt(296), VIEW, NOTE);
    expect(p.above).toBe(true);
    expect(p.top + NOTE.height).toBe(296 - NOTE_GAP_PX);
    expect(p.top).toBeGreaterThanOrEqual(VIEW.top); // not under the sticky head
    expect(p.growBy).toBe(0);
  });

  it("flips exactly when the room under the field is less than the note and its gap", () => {
    const fits = VIEW.bottom - NOTE.height - NOTE_GAP_PX - 24; // the lowest field top it fits under
    expect(placeCellNote(fieldAt(fits), VIEW, NOTE).above).toBe(false);
    expect(placeCellNote(fieldAt(fits + 1), VIEW, NOTE).above).toBe(true);
  });

  it("in a view too short for it on either side, draws it under the field and says what the view lacks", () => {
    // a table of one row: the view is that row
    const one = { ...VIEW, bottom: VIEW.top + 24 };
    const p = placeCellNote(fieldAt(VIEW.top), one, NOTE);
    expect(p).toMatchObject({ above: false, growBy: NOTE.height + NOTE_GAP_PX, shown: true });
    expect(p.top).toBe(VIEW.top + 24 + NOTE_GAP_PX);
    // grown by that, it fits with nothing more to grow
    const grown = { ...one, bottom: one.bottom + p.growBy };
    expect(placeCellNote(fieldAt(VIEW.top), grown, NOTE)).toMatchObject({ above: false, growBy: 0 });
  });

  it("keeps the note inside the view sideways: moved left from a field near the right edge", () => {
    expect(placeCellNote(fieldAt(124, 350), VIEW, NOTE).left).toBe(VIEW.right - NOTE.width);
    // wider than the view: at its left edge
    expect(placeCellNote(fieldAt(124, 350), VIEW, { width: 500, height: 30 }).left).toBe(VIEW.left);
  });

  it("hides the note of a field scrolled out of the view (under the head or past the foot), growing nothing", () => {
    for (const top of [VIEW.top - 20, VIEW.bottom - 4, VIEW.bottom + 50]) {
      const p = placeCellNote(fieldAt(top), VIEW, NOTE);
      expect(p.shown, `field at ${top}`).toBe(false);
      expect(p.growBy, `field at ${top}`).toBe(0);
    }
    expect(placeCellNote(fieldAt(VIEW.bottom - 12), VIEW, NOTE).shown).toBe(true); // its middle in view
  });
});
