/**
 * Layout probes the editor's end-to-end tests share: where the stage and its canvas are (to tell
 * whether something moved them), and whether a button can be clicked where it shows (its centre in
 * the window, and nothing covering it there), or whether any element is uncovered at its centre.
 */
import type { Locator, Page } from "playwright-core";

/** The stage's and the canvas's boxes in the page (not the window: the page may be scrolled), as
 *  one string to compare ("x y width height" each). */
export function stageBoxes(page: Page): Promise<string> {
  return page.evaluate(() => {
    const box = (el: Element | null) => {
      const r = el!.getBoundingClientRect();
      return `${r.x + window.scrollX} ${r.y + window.scrollY} ${r.width} ${r.height}`;
    };
    return `stage ${box(document.querySelector("main.stage"))}, canvas ${box(document.querySelector("[data-testid=scene-canvas]"))}`;
  });
}

/** Whether the button named `name` (exactly) within `scope` has its centre in the window and is
 *  itself the element there (nothing covers it). */
export function buttonUncovered(scope: Page | Locator, name: string): Promise<boolean> {
  return scope.getByRole("button", { name, exact: true }).evaluate((el) => {
    const r = el.getBoundingClientRect();
    const x = r.x + r.width / 2;
    const y = r.y + r.height / 2;
    if (x < 0 || y < 0 || x > window.innerWidth || y > window.innerHeight) return false;
    return el.contains(document.elementFromPoint(x, y));
  });
}

/** Whether the element `target` locates is the element at its own centre (or holds it): nothing
 *  covers it there. A centre outside the window has no element, so it counts as covered. */
export function centreUncovered(target: Locator): Promise<boolean> {
  return target.evaluate((el) => {
    const r = el.getBoundingClientRect();
    return el.contains(document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2));
  });
}
