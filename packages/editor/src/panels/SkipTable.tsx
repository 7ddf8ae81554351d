/**
 * "Skip the <name> table": a button before a long table, shown only while focused, that moves the
 * focus to the first control after the table (skipPast.ts), so reaching the panels below does not
 * take a Tab press per cell. Rendered only when the table has rows to skip.
 */
import type { RefObject } from "react";
import { nextTabbable } from "./skipPast";

export function SkipTable({ name, region }: { name: string; region: RefObject<HTMLElement | null> }) {
  return (
    <button
      type="button"
      className="skip-table"
      onClick={() => {
        const el = region.current;
        if (el) nextTabbable(el)?.focus();
      }}
    >
      Skip the {name} table
    </button>
  );
}
