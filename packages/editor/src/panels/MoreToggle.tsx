/**
 * The More / Less button of a text kept to one line (the message bar's message: MessageBar; a
 * persistent notice's text: NoticeText). Contract: `MoreToggle` draws nothing while the text is
 * neither cut nor shown whole; otherwise one button named by its label, "More" (the text cut:
 * aria-expanded false) or "Less" (shown whole: aria-expanded true), calling `onToggle` when pressed.
 * `useShownWhole(key)` keeps which text is shown whole: the one whose key was current when More was
 * pressed, so that another key (the next message, even of the same text; another notice text) shows
 * on its line first; a null key (no text) is never shown whole.
 */
import { useState } from "react";

export interface MoreToggleProps {
  /** The text is wider than its line (useTextCut). */
  cut: boolean;
  /** The text is shown whole. */
  open: boolean;
  /** The button's class: where it is drawn (styles/message.css, styles/notices.css). */
  className: string;
  onToggle: () => void;
}

export function MoreToggle({ cut, open, className, onToggle }: MoreToggleProps) {
  if (!cut && !open) return null;
  return (
    <button type="button" className={className} aria-expanded={open} onClick={onToggle}>
      {open ? "Less" : "More"}
    </button>
  );
}

/** Whether the text of `key` is shown whole, and the toggle between whole and cut for that key. */
export function useShownWhole<K>(key: K | null): [open: boolean, toggle: () => void] {
  const [openFor, setOpenFor] = useState<K | null>(null);
  const open = key !== null && openFor === key;
  return [open, () => setOpenFor(open ? null : key)];
}
