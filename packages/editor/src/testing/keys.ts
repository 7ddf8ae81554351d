/**
 * Key presses for the keyboard tests: a keydown dispatched on a target as the browser would (it
 * bubbles, it can be cancelled), and whether the page left the browser's own handling alone.
 */

/** Presses `key` on `target`; returns whether the page kept the browser's own handling. */
export function press(target: EventTarget, key: string, mods: KeyboardEventInit = {}): boolean {
  const e = new KeyboardEvent("keydown", { key, bubbles: true, cancelable: true, ...mods });
  target.dispatchEvent(e);
  return !e.defaultPrevented;
}
