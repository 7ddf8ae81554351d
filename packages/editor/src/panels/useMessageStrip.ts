/**
 * The side column's strip for a message hanging under the header (styles/message.css: from 1001 px,
 * where the header's line leaves the message slot under 240 px, 1027 to 1382 px at 900 px high, the
 * message hangs under the header over the top of the side column). Contract: while the slot is such
 * a slot (its probe, `.message-hang-probe`, has `--message-hangs: 1` there and only there, and is
 * laid out where a one-line message hangs: the container query decides, not a window width), the `.app` around
 * `slot` gets `--message-strip`, the px from the header's foot to the foot of the message hanging
 * there (of a one-line message, the probe's, when none is shown or it is shorter) plus a gap, and
 * the side column starts that far under the header (layout.css): the message covers none of its
 * panels, however far the column is scrolled. The strip is kept with no message shown, so a message
 * coming or going never moves the column under the pointer (a message comes with every add, load
 * and refusal, and opening a cell takes it away: the cell would jump from under the click); only
 * More, pressed by the author, lowers the column, by the lines it shows. Elsewhere the strip is 0.
 * Measured again when the slot, the header or the message changes size, and on every `message`.
 */
import { type RefObject, useLayoutEffect } from "react";

/** Space (px) between the hanging message's foot and the side column's top. */
export const STRIP_GAP_PX = 4;

/** The strip (px) the side column leaves under the header for the message hanging there; 0 elsewhere. */
export function messageStrip(header: DOMRect, probe: DOMRect | null, message: DOMRect | null): number {
  if (probe === null) return 0;
  const foot = Math.max(probe.bottom, message?.bottom ?? 0);
  return Math.max(0, Math.ceil(foot - header.bottom + STRIP_GAP_PX));
}

export function useMessageStrip(slot: RefObject<HTMLElement | null>, message: unknown): void {
  // biome-ignore lint/correctness/useExhaustiveDependencies: a new message is a new element to observe
  useLayoutEffect(() => {
    const el = slot.current;
    const header = el?.closest("header");
    const app = el?.closest<HTMLElement>(".app");
    const probe = el?.querySelector<HTMLElement>(".message-hang-probe");
    if (!el || !header || !app || !probe) return;
    const update = () => {
      const hangs = getComputedStyle(probe).getPropertyValue("--message-hangs").trim() === "1";
      const shown = el.querySelector(".message");
      const px = messageStrip(
        header.getBoundingClientRect(),
        hangs ? probe.getBoundingClientRect() : null,
        hangs && shown ? shown.getBoundingClientRect() : null,
      );
      const value = `${px}px`;
      if (app.style.getPropertyValue("--message-strip") !== value)
        app.style.setProperty("--message-strip", value);
    };
    update();
    const ro = typeof ResizeObserver === "undefined" ? null : new ResizeObserver(update);
    ro?.observe(el);
    ro?.observe(header);
    const shown = el.querySelector(".message");
    if (shown) ro?.observe(shown);
    // (a window crossing 500 px high changes the layout without always resizing the slot)
    window.addEventListener("resize", update);
    return () => {
      ro?.disconnect();
      window.removeEventListener("resize", update);
    };
  }, [slot, message]);
}
