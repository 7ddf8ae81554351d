/**
 * A stand-in for text layout in jsdom, which lays nothing out: while `layOutText()` is in force, an
 * element's text is "cut" (scrollWidth > clientWidth) when it is longer than FITS characters, which
 * is what the message bar and the notices read to offer More. `restoreTextLayout()` (an afterEach)
 * puts jsdom's own scrollWidth and clientWidth back.
 */

/** How many characters a line holds under `layOutText`. */
export const FITS = 20;

const widths = {
  scrollWidth: { get: (el: HTMLElement) => (el.textContent ?? "").length },
  clientWidth: { get: () => FITS },
};
const saved = Object.keys(widths).map(
  (k) => [k, Object.getOwnPropertyDescriptor(HTMLElement.prototype, k)] as const,
);

/** Makes every element's scrollWidth its text's length and its clientWidth FITS. */
export function layOutText(): void {
  for (const [k, d] of Object.entries(widths))
    Object.defineProperty(HTMLElement.prototype, k, {
      configurable: true,
      get(this: HTMLElement) {
        return d.get(this);
      },
    });
}

/** Puts jsdom's scrollWidth and clientWidth back as they were before `layOutText`. */
export function restoreTextLayout(): void {
  for (const [k, d] of saved) {
    if (d) Object.defineProperty(HTMLElement.prototype, k, d);
    else delete (HTMLElement.prototype as unknown as Record<string, unknown>)[k];
  }
}
