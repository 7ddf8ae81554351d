/**
 * End-to-end helpers for the persistent notices (newer work in another tab, an autosaved scene
 * refused at start): showing them as the editor does (autosave.ts, boot.ts), finding them, and the
 * strip of the canvas they cover.
 */
import type { Page } from "playwright-core";

/** The reason the refused scene's notice gives (as long as a real one: two lines at 700 px). */
export const REFUSED_REASON =
  "bodies[0].r: must be a positive number (got -1); the scene file says so at line 12 of 80";

/** Shows (or with false takes down) the notices as the editor does. */
export function setNotices(page: Page, newer: boolean, refused: boolean): Promise<void> {
  return page.evaluate(
    ([newer, refused, reason]) => {
      type Ui = { ui: { setState(s: Record<string, unknown>): void } };
      (window as unknown as { chapgame: Ui }).chapgame.ui.setState({
        newerWork: newer ? { tab: "other-tab", savedAt: Date.UTC(2026, 0, 2, 15, 4) } : null,
        refusedScene: refused ? { reason, text: '{"bodies":[{"id":"a","r":-1}]}', tab: null } : null,
      });
    },
    [newer, refused, REFUSED_REASON] as const,
  );
}

export const newerNotice = (page: Page) => page.getByRole("status", { name: "Newer work in another tab" });
export const refusedNotice = (page: Page) => page.getByRole("alert", { name: "Autosaved scene refused" });

/** How far below the canvas's top the lowest notice reaches (CSS px; 0 with none shown). */
export function noticesBottom(page: Page): Promise<number> {
  return page.evaluate(() => {
    const top = document.querySelector("[data-testid=scene-canvas]")!.getBoundingClientRect().top;
    const bottoms = Array.from(document.querySelectorAll(".stage-notices > *")).map(
      (n) => n.getBoundingClientRect().bottom - top,
    );
    return Math.max(0, ...bottoms);
  });
}
