/**
 * Row windowing for the scrolling tables (Bodies, Event log): of `count` rows of equal height, only
 * those in the scroll container's view (plus OVERSCAN rows each side) are rendered; spacer rows
 * (role presentation) keep the scroll height. While playing, a table refresh then lays out and paints about
 * a dozen rows instead of sixty (the profile of 2,000 discs showed each refresh of the full tables as
 * a frame of 10-25 ms of layout and paint). Where nothing is laid out (no height: jsdom, a hidden
 * panel) every row is rendered.
 */
import { type RefObject, useEffect, useLayoutEffect, useRef, useState } from "react";

/** Rows rendered beyond each edge of the view. */
export const OVERSCAN = 4;
/** Row height assumed until one is measured (CSS px): the tables' rows (styles/table-targets.css). */
const DEFAULT_ROW_PX = 24;

export interface RowWindow {
  start: number;
  end: number;
  /** Height (px) of the spacer before row `start`. */
  before: number;
  /** Height (px) of the spacer after row `end - 1`. */
  after: number;
}

/** The scroll box as last measured (on scroll and resize): read without forcing a layout. */
export interface BoxGeometry {
  scroll: number;
  view: number;
  head: number;
  row: number;
}

/** The rows [start, end) of `count` to render in a view of `viewPx` scrolled to `scrollPx`. */
export function rowWindow(
  count: number,
  scrollPx: number,
  viewPx: number,
  headPx: number,
  rowPx: number,
  overscan: number = OVERSCAN,
): RowWindow {
  if (viewPx <= 0 || rowPx <= 0) return { start: 0, end: count, before: 0, after: 0 };
  const first = Math.floor(Math.max(0, scrollPx - headPx) / rowPx);
  const start = Math.max(0, Math.min(count, first - overscan));
  const end = Math.min(count, first + Math.ceil(viewPx / rowPx) + 1 + overscan);
  return { start, end: Math.max(start, end), before: start * rowPx, after: Math.max(0, count - end) * rowPx };
}

/** A part of a windowed table: a row (its index), or a spacer of `gap` px standing for the rows from `from` on, not rendered. */
export type RowRun = { row: number } | { gap: number; from: number };

/**
 * The rows to render, in order: those of the window `win` and the `held` rows (indices of `count`)
 * outside it (a row holding an open cell, useHeldRows.ts), each at its own place, with spacers of
 * `rowPx` per row between them, so the scroll height and every row's place are as if all rows were
 * rendered.
 */
export function rowRuns(win: RowWindow, held: readonly number[], count: number, rowPx: number): RowRun[] {
  const rows = new Set<number>();
  for (let i = win.start; i < win.end; i++) rows.add(i);
  for (const i of held) if (i >= 0 && i < count) rows.add(i);
  const runs: RowRun[] = [];
  let next = 0;
  for (const i of [...rows].sort((a, b) => a - b)) {
    if (i > next) runs.push({ gap: (i - next) * rowPx, from: next });
    runs.push({ row: i });
    next = i + 1;
  }
  if (count > next) runs.push({ gap: (count - next) * rowPx, from: next });
  return runs;
}

/**
 * The window of rows to render in the scroll container `ref` (whose table has a thead), and the
 * container's geometry as last measured.
 */
export function useRowWindow(
  ref: RefObject<HTMLElement | null>,
  count: number,
): RowWindow & { geometry: BoxGeometry } {
  const [geometry, setGeometry] = useState<BoxGeometry>({ scroll: 0, view: 0, head: 0, row: DEFAULT_ROW_PX });
  const measure = useRef<() => void>(() => {});

  useEffect(() => {
    const el = ref.current;
    if (!el) return;
    const update = () => {
      const head = el.querySelector("thead")?.getBoundingClientRect().height ?? 0;
      const rowEl = el.querySelector("tbody tr:not(.spacer)");
      const measured = rowEl?.getBoundingClientRect().height ?? 0;
      setGeometry((g) => {
        const row = measured > 0 ? measured : g.row;
        return g.scroll === el.scrollTop && g.view === el.clientHeight && g.head === head && g.row === row
          ? g
          : { scroll: el.scrollTop, view: el.clientHeight, head, row };
      });
    };
    measure.current = update;
    update();
    el.addEventListener("scroll", update, { passive: true });
    const ro = typeof ResizeObserver === "undefined" ? null : new ResizeObserver(update);
    ro?.observe(el);
    return () => {
      el.removeEventListener("scroll", update);
      ro?.disconnect();
    };
  }, [ref]);

  // Measure the row height once rows exist (and again when the table empties and refills).
  const hasRows = count > 0;
  useLayoutEffect(() => {
    if (hasRows) measure.current();
  }, [hasRows]);

  return { ...rowWindow(count, geometry.scroll, geometry.view, geometry.head, geometry.row), geometry };
}

/** A spacer row of `height` px standing for rows not rendered (presentational: not a row to assistive technology). */
export function spacerRow(key: string, height: number, columns: number) {
  return height > 0 ? (
    // biome-ignore lint/a11y/noInteractiveElementToNoninteractiveRole: a spacer row is neither interactive nor a row of data; its role keeps it out of the table's rows for assistive technology and tests
    <tr key={key} role="presentation" className="spacer">
      <td colSpan={columns} style={{ height, padding: 0 }} />
    </tr>
  ) : null;
}
