/**
 * End-to-end, in Debian's Chromium: the tables' targets (Bodies, Lines, Points, Event log) are at
 * least 24 x 24 px (WCAG 2.2, 2.5.8) at every window size the editor's end-to-end tests use, and
 * none overlaps another: a cell's value, a row's Delete and the Event log's ✕, with a scene of 30
 * bodies, 20 lines, 20 points and 10 later actions (every table scrolls). They were 17 px high (a
 * value 19.5 px wide), 21 (Delete) and 15 (✕, 20.8 wide) in rows of 23 and 17 px; every row is now
 * 24 px, the Event log's entries (each a target: pressed, it goes to its event) too. The row window
 * (useRowWindow.tsx) assumes rows of equal height: every row rendered is as high as the others, and
 * scrolled to its middle or its end each table's rendered rows fill its view at 1400 x 900, 1027 x
 * 900 and 700 x 420; ↓ walks the Event log's entries past those first rendered. The other targets
 * are editor-targets'.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, POLL_TIMEOUT_MS, poll } from "./editorForFile.js";
import { waitFor } from "./harness.js";
import { loadScene } from "./pageEditor.js";
import { expectTargets, MIN_TARGET_PX, TARGET_SIZES, type Target } from "./targetBoxes.js";
import { forEachWindowSize, type WindowSize } from "./windowSize.js";

/** 30 moving bodies in a walled box, 20 lines and 20 points beside it, and 10 velocities given
 *  later (Event log entries with a ✕ among the collisions). */
function manyRows(): object {
  const actions: object[] = [];
  const corners = [
    [0, 0],
    [100, 0],
    [100, 100],
    [0, 100],
  ];
  for (const [i, p1] of corners.entries())
    actions.push({
      time: 0,
      type: "addLine",
      id: `wall${i + 1}`,
      p1,
      p2: corners[(i + 1) % 4],
      kind: "segment",
    });
  for (let i = 1; i <= 16; i++)
    actions.push({
      time: 0,
      type: "addLine",
      id: `l${i}`,
      p1: [200 + 2 * i, 0],
      p2: [200 + 2 * i, 50],
      kind: "segment",
    });
  for (let i = 1; i <= 20; i++)
    actions.push({ time: 0, type: "addPoint", id: `p${i}`, p: [300 + 3 * i, 10] });
  for (let i = 0; i < 30; i++) {
    const [x, y] = [10 + (i % 6) * 15, 10 + Math.floor(i / 6) * 15];
    actions.push({ time: 0, type: "addBody", id: `b${i + 1}`, x, y, r: 3, m: 1, mu: 0, v: [7 + i, 5 - i] });
  }
  for (let i = 0; i < 10; i++)
    actions.push({ time: 0.5 * (i + 1), type: "giveVelocity", id: `b${i + 1}`, v: [20, -i] });
  return { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions };
}

const editor = editorForFile({
  afterOpen: async ({ page }) => {
    await loadScene(
      page,
      manyRows(),
      { useTime: true, seconds: 5, useEvents: false, autoExtend: false },
      60_000,
    );
    // the tables show it once they refresh
    for (const [table, id] of [
      ["Bodies", "b1"],
      ["Lines", "wall1"],
      ["Points", "p1"],
    ] as const) {
      const cell = page.getByRole("table", { name: table }).getByLabel(`${id} id`, { exact: true });
      await waitFor(async () => (await cell.count()) === 1, POLL_TIMEOUT_MS);
    }
    const removable = page.locator("table[aria-label='Event log'] button[data-action-index]");
    await waitFor(async () => (await removable.count()) > 9, POLL_TIMEOUT_MS);
  },
});

const TABLES = ["Bodies", "Lines", "Points", "Event log"] as const;

/** What a table shows: its targets (values, and row buttons), those of them wholly in its box's
 *  view (not under its head nor under the sticky column of row buttons), and its rows' heights. */
interface TableTargets {
  all: Target[];
  inView: Target[];
  rowHeights: number[];
}

function tableTargets(table: string): Promise<TableTargets> {
  return editor.page.evaluate((table) => {
    const el = document.querySelector(`table[aria-label="${table}"]`)!;
    const box = el.closest(".table-scroll")!;
    const view = box.getBoundingClientRect();
    const top = view.top + el.querySelector("thead")!.getBoundingClientRect().height;
    const bottom = view.top + box.clientHeight;
    const rowEnd = el.querySelector("tbody td.row-end")?.getBoundingClientRect().left ?? view.right;
    const all: Target[] = [];
    const inView: Target[] = [];
    for (const t of Array.from(el.querySelectorAll("tbody .cell-view, tbody td.row-end > button"))) {
      const r = t.getBoundingClientRect();
      const target = {
        name: t.getAttribute("aria-label")!,
        x: r.x,
        y: r.y,
        width: r.width,
        height: r.height,
      };
      all.push(target);
      const right = t.closest("td.row-end") ? view.left + box.clientWidth : rowEnd;
      if (
        r.top >= top - 0.5 &&
        r.bottom <= bottom + 0.5 &&
        r.left >= view.left - 0.5 &&
        r.right <= right + 0.5
      )
        inView.push(target);
    }
    const rows = el.querySelectorAll("tbody tr:not(.spacer)");
    return { all, inView, rowHeights: Array.from(rows, (r) => r.getBoundingClientRect().height) };
  }, table);
}

describe("the tables' targets", () => {
  it("a value, a row's Delete and the Event log's ✕ are at least 24 x 24 px at every window size, in rows of 24 px, none overlapping another", async () => {
    await forEachWindowSize(editor.page, TARGET_SIZES, async (width, height) => {
      for (const table of TABLES) {
        const at = `${width} x ${height}, ${table}`;
        const { all, inView, rowHeights } = await tableTargets(table);
        // every table scrolls: more rows rendered than its view holds, and a row's targets in view
        expect(rowHeights.length, at).toBeGreaterThan(9);
        expect(
          inView.filter((t) => t.name.startsWith("Delete") || t.name.startsWith("Remove")).length,
          at,
        ).toBeGreaterThan(1);
        // every one rendered at least 24 x 24 (a narrow window's sticky column of row buttons covers
        // the values scrolled under it: those in view are checked for overlaps)
        for (const t of all) {
          expect(t.width, `${at}: ${t.name} wide`).toBeGreaterThanOrEqual(MIN_TARGET_PX);
          expect(t.height, `${at}: ${t.name} high`).toBeGreaterThanOrEqual(MIN_TARGET_PX);
        }
        expectTargets(`${at}, in view`, inView);
        // the row window's equal rows, each a target (the Event log's entries are pressed)
        for (const h of rowHeights) expect(h, `${at}: a row`).toBe(rowHeights[0]);
        expect(rowHeights[0], `${at}: the rows`).toBeGreaterThanOrEqual(MIN_TARGET_PX);
      }
    });
  });
});

/** The rows in view of table `table`'s box scrolled to `at` (0 its top, 1 its end), once rendered:
 *  the gap (px) between the view's top (under the head) and the first rendered row's top (positive:
 *  an empty strip), the same at the bottom, and whether a spacer (rows not rendered) ends the table. */
async function scrolledView(
  table: string,
  at: number,
): Promise<{ top: number; bottom: number; spacerLast: boolean }> {
  const box = editor.page.locator(".table-scroll", {
    has: editor.page.locator(`table[aria-label="${table}"]`),
  });
  await box.evaluate((el, at) => {
    el.scrollIntoView({ block: "nearest" });
    el.scrollTop = at * (el.scrollHeight - el.clientHeight);
  }, at);
  return box.evaluate((el) => {
    const view = el.getBoundingClientRect();
    const top = view.top + el.querySelector("thead")!.getBoundingClientRect().height;
    const bottom = view.top + el.clientHeight;
    const rows = Array.from(el.querySelectorAll("tbody tr:not(.spacer)"), (r) => r.getBoundingClientRect());
    return {
      top: rows[0]!.top - top,
      bottom: bottom - rows.at(-1)!.bottom,
      spacerLast: el.querySelector("tbody")!.lastElementChild!.classList.contains("spacer"),
    };
  });
}

/** Sizes where the row window is checked: a wide window, a narrow one of two columns, a short one. */
const WINDOW_CHECK: WindowSize[] = [
  [1400, 900],
  [1027, 900],
  [700, 420],
];

describe("the tables' row window with rows of 24 px", () => {
  it("scrolled to the middle or the end, the rows rendered fill each table's view; at the end the last row is rendered", async () => {
    await forEachWindowSize(editor.page, WINDOW_CHECK, async (width, height) => {
      for (const table of TABLES) {
        const at = `${width} x ${height}, ${table}`;
        for (const where of [0.5, 1]) {
          // (polled: the row window renders the rows in view once it has measured the scroll)
          await poll(async () => {
            const v = await scrolledView(table, where);
            // at the end, no rows left unrendered after the last one rendered
            const rowsAfter = where === 1 && v.spacerLast;
            return { at, where, topCovered: v.top <= 0.5, bottomCovered: v.bottom <= 0.5, rowsAfter };
          }).toEqual({ at, where, topCovered: true, bottomCovered: true, rowsAfter: false });
        }
        await scrolledView(table, 0);
      }
    });
  });

  it("↓ walks the Event log's entries one by one past those first rendered, each in view as it is focused", async () => {
    const entries = editor.page.getByRole("table", { name: "Event log" }).locator("tbody tr[data-entry]");
    await entries.first().focus();
    const walked: string[] = [];
    for (let i = 0; i < 25; i++) {
      const focused = editor.page.locator("tr[data-entry]:focus");
      const inView = await focused.evaluate((row) => {
        const box = row.closest(".table-scroll")!.getBoundingClientRect();
        const r = row.getBoundingClientRect();
        return r.top >= box.top - 0.5 && r.bottom <= box.bottom + 0.5;
      });
      expect(inView, `entry ${i}`).toBe(true);
      walked.push((await focused.getAttribute("data-entry"))!);
      await editor.page.keyboard.press("ArrowDown");
    }
    // 25 entries, each another (the log's view holds 10 to 14, 19 to 23 rendered)
    expect(new Set(walked).size).toBe(25);
  });
});

describe("the Event log's filter and Skip with rows of 24 px", () => {
  it("filtered by a body it lists only that body's entries, in rows of 24 px; Skip then passes the log", async () => {
    const filter = editor.page.getByRole("textbox", { name: "Filter by body" });
    await filter.fill("b3");
    const log = editor.page.getByRole("table", { name: "Event log" });
    const participants = log.locator("tbody tr[data-entry] td:nth-child(3)");
    await poll(async () => {
      const all = await participants.allTextContents();
      return all.length > 0 && all.every((ids) => ids.split(", ").includes("b3"));
    }).toBe(true);
    const { rowHeights } = await tableTargets("Event log");
    expect(new Set(rowHeights)).toEqual(new Set([MIN_TARGET_PX]));
    const skip = editor.page.getByRole("button", { name: "Skip the Event log table" });
    await skip.focus();
    await editor.page.keyboard.press("Enter");
    const focusInLog = await editor.page.evaluate(
      () => document.activeElement?.closest(".table-scroll.log") !== null,
    );
    expect(focusInLog).toBe(false);
    expect(await skip.evaluate((el) => el === document.activeElement)).toBe(false);
    await filter.fill("");
  });
});
