/**
 * An editable table cell: an input showing a live value; while focused it holds the user's draft.
 * Enter or leaving the cell commits a changed draft through `onCommit`, which resolves to an error
 * message (the value is refused and the message shown in place, the draft kept for correction) or
 * null (accepted). Escape restores the live value.
 */
import { useId, useState } from "react";

export interface EditableCellProps {
  label: string;
  value: string;
  onCommit: (text: string) => Promise<string | null>;
  size?: number;
}

export function EditableCell({ label, value, onCommit, size = 7 }: EditableCellProps) {
  const [draft, setDraft] = useState<string | null>(null);
  const [error, setError] = useState<string | null>(null);
  const errorId = useId();

  const commit = async () => {
    if (draft === null || draft === value) {
      setDraft(null);
      setError(null);
      return;
    }
    const err = await onCommit(draft.trim());
    if (err === null) {
      setDraft(null);
      setError(null);
    } else setError(err);
  };

  return (
    <span className="cell">
      <input
        aria-label={label}
        aria-invalid={error !== null}
        aria-describedby={error ? errorId : undefined}
        size={size}
        value={draft ?? value}
        onFocus={() => setDraft(value)}
        onChange={(e) => setDraft(e.target.value)}
        onBlur={() => {
          if (error === null) void commit();
        }}
        onKeyDown={(e) => {
          if (e.key === "Enter") void commit();
          if (e.key === "Escape") {
            setDraft(null);
            setError(null);
            e.currentTarget.blur();
          }
        }}
      />
      {error && (
        <span id={errorId} role="alert" className="cell-error">
          {error}
        </span>
      )}
    </span>
  );
}

/** Parses a number typed in a cell ("Infinity" and "∞" allowed); null when it is not a number. */
export function parseNumber(text: string): number | null {
  const t = text.trim();
  if (t === "∞" || t === "Infinity" || t === "inf") return Number.POSITIVE_INFINITY;
  if (t === "" || !/^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(t)) return null;
  return Number(t);
}

/** A short display of a number: 6 significant digits, no trailing zeros, ∞ for infinities. */
export function formatNumber(x: number): string {
  if (x === Number.POSITIVE_INFINITY) return "∞";
  if (x === Number.NEGATIVE_INFINITY) return "-∞";
  if (Object.is(x, -0) || Math.abs(x) < 1e-12) return "0";
  return String(Number(x.toPrecision(6)));
}
