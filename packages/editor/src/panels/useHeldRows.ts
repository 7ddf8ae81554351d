/**
 * The rows of a windowed table that hold an open cell (useRowWindow.tsx renders only the rows in
 * view). A row scrolled more than OVERSCAN rows out of the view was unmounted, and with it its open
 * cell's state: a refused draft (r = -1) and its refusal were gone when the row came back. Contract:
 * `holder(id)` is the EditableCell `onOpenChange` of the cells of row `id`; `held` is the set of
 * rows with at least one cell open (a refused draft stays open, and another cell may be opened
 * meanwhile), which the table renders wherever they are, in view or not (rowRuns). A row that leaves
 * the table (its object deleted, renamed, or its scene replaced: the tables key rows by the scene,
 * EditorSession.sceneSerial) unmounts its cells, which close: the draft goes with its object and is
 * never applied to another.
 */
import { useCallback, useRef, useState } from "react";

export interface HeldRows {
  held: ReadonlySet<string>;
  holder: (id: string) => (open: boolean) => void;
}

export function useHeldRows(): HeldRows {
  /** Open cells per row id. */
  const counts = useRef(new Map<string, number>());
  const [held, setHeld] = useState<ReadonlySet<string>>(() => new Set());
  const holder = useCallback(
    (id: string) => (open: boolean) => {
      const n = (counts.current.get(id) ?? 0) + (open ? 1 : -1);
      if (n > 0) counts.current.set(id, n);
      else counts.current.delete(id);
      const now = n > 0;
      setHeld((s) => {
        if (s.has(id) === now) return s;
        const next = new Set(s);
        if (now) next.add(id);
        else next.delete(id);
        return next;
      });
    },
    [],
  );
  return { held, holder };
}
