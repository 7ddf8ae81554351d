import { describe, expect, it } from "vitest";
import { messageStrip, STRIP_GAP_PX } from "./useMessageStrip";

/** A box from `top` to `bottom` (px), as getBoundingClientRect gives one. */
const box = (top: number, bottom: number) => ({ top, bottom, left: 0, right: 100 }) as DOMRect;
/** The header of a 1100 px window: one line, 42 px; a one-line message hangs 4 px under it. */
const HEADER = box(0, 42);
const ONE_LINE = box(46, 70);

describe("messageStrip", () => {
  it("is 0 where the message does not hang under the header (no probe laid out), whatever is shown", () => {
    expect(messageStrip(HEADER, null, null)).toBe(0);
    expect(messageStrip(HEADER, null, box(6, 36))).toBe(0);
  });

  it("keeps a one-line message's strip with no message shown, so a message coming never moves the column", () => {
    expect(messageStrip(HEADER, ONE_LINE, null)).toBe(70 - 42 + STRIP_GAP_PX);
    expect(messageStrip(HEADER, ONE_LINE, ONE_LINE)).toBe(messageStrip(HEADER, ONE_LINE, null));
  });

  it("grows to the foot of a message shown whole (More), in whole px", () => {
    expect(messageStrip(HEADER, ONE_LINE, box(46, 126.4))).toBe(Math.ceil(126.4 - 42 + STRIP_GAP_PX));
  });

  it("is never negative (a probe not laid out measures 0 x 0 at the page's top)", () => {
    expect(messageStrip(HEADER, box(0, 0), null)).toBe(0);
  });
});
