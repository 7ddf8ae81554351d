/**
 * An editable table cell. At rest it is a button showing the live value (cheap: tables of hundreds
 * of cells stay light to lay out and paint while values change); clicking or focusing it opens an
 * input. Until the user types, the input follows the live value (so a cell opened while playing shows
 * the values of the time playback paused at once the table refreshes), and Enter or leaving it
 * commits nothing. Once the user has typed, Enter or leaving the input commits a changed draft through
 * `onCommit`, which resolves to an error message (the value is refused, the message shown in place,
 * the draft kept for correction; once the time moves, its row shows another time, and a note in
 * place of the refusal says where Enter applies the draft) or null (accepted). A commit an Undo took back during its check
 * (UNDONE_DURING_CHECK) closes the cell on the scene's value as an accepted one does: the Undo says
 * what it did, and the draft it undid is not committed again. Escape closes without committing.
 * A refusal is shown under the input and describes it (aria-describedby); in a table it is drawn
 * over the rows next to the field, not in its row, which keeps its height (useCellNote.ts); it is an alert only when
 * the message bar does not show the same text already (the editor's refusals go there too: a screen
 * reader announced each twice). Both the button and the input carry `label` as their accessible name. Enter is consumed by the
 * input (its default prevented), so closing the cell never lets it activate the button refocused.
 * A refusal that only holds until the history reaches the time (Editor.refusalChanged: "still being
 * computed" after an undo) is dropped once it does, the draft kept for Enter.
 * A key typed into the field while its row is scrolled out of the table's view (a row holding an open
 * cell stays rendered and focused there: useHeldRows.ts) brings the row back into view first
 * (revealField.ts). While it holds a draft not being committed, the cell records it (with its
 * `owner`) in the editor's OpenDrafts (useOpenDraft.ts): a step that takes it away says so.
 * Opening a cell pauses playback (inside an editor): the edit applies at the current time, and the
 * values the cell and its row show are those of that time, not of a moment that playback has left.
 */
import { useContext, useEffect, useId, useRef, useState, useSyncExternalStore } from "react";
import { EditorContext } from "../EditorContext";
import type { DraftOwner } from "../openDrafts";
import { UNDONE_DURING_CHECK } from "../remote/protocol";
import { revealField, revealsField } from "./revealField";
import { useCellNote } from "./useCellNote";
import { useOpenDraft } from "./useOpenDraft";

export interface EditableCellProps {
  label: string;
  value: string;
  onCommit: (text: string) => Promise<string | null>;
  size?: number;
  /**
   * Told when the cell opens (true) and when it closes or unmounts (false): a windowed table keeps
   * the row of an open cell rendered out of view, with its draft (useHeldRows.ts).
   */
  onOpenChange?: (open: boolean) => void;
  /**
   * Whether a commit applies at the current time (the default: the tables' and Globals' edits are
   * actions at that time), so that a refused draft says where Enter applies it once the time moves.
   * False for a cell whose commit does not depend on the time (the refused action's fields,
   * RefusedActionRow.tsx): its refusal stays as it was given.
   */
  atCurrentTime?: boolean;
  /**
   * The object and field of a table's cell: a delete, a rename or a removed add of that object says
   * that the draft typed here was dropped with it (openDrafts.ts); a load says so of every draft.
   */
  owner?: DraftOwner;
}

/** A commit not answered after this many milliseconds shows that it is being checked. */
export const SLOW_COMMIT_MS = 300;

const noSubscription = () => () => {};

export function EditableCell({
  label,
  value,
  onCommit,
  size = 7,
  onOpenChange,
  atCurrentTime = true,
  owner,
}: EditableCellProps) {
  // null: at rest (a button); open: `typed` is null until the user types (the input then shows the
  // live value), then the text typed.
  const [edit, setEdit] = useState<{ typed: string | null } | null>(null);
  const [error, setError] = useState<string | null>(null);
  const [waiting, setWaiting] = useState(false);
  // a draft being committed is not one an edit taking its object away drops (it was applied first)
  const [committing, setCommitting] = useState(false);
  const errorId = useId();
  const editor = useContext(EditorContext);
  // The message bar's text: a refusal it shows already (as an alert) is not announced again here.
  const inBar = useSyncExternalStore(editor?.ui.subscribe ?? noSubscription, () =>
    error === null ? false : editor?.ui.getState().message?.text === error,
  );
  // A commit in flight: Enter then a click elsewhere (blur) before the edit was applied committed the
  // same draft twice (two undo steps for one edit).
  const pending = useRef(false);
  const open = () => {
    if (editor?.ui.getState().playing) editor.ui.setState({ playing: false });
    // A message left by an earlier refusal would sit beside this cell's own (the audit saw two).
    if (editor?.ui.getState().message) editor.ui.setState({ message: null });
    setEdit({ typed: null });
  };

  const isOpen = edit !== null;
  const openChange = useRef(onOpenChange);
  openChange.current = onOpenChange;
  useEffect(() => {
    if (!isOpen) return;
    openChange.current?.(true);
    return () => openChange.current?.(false);
  }, [isOpen]);

  // Closed by Enter or Escape, the cell keeps the focus (on its button, without opening again): it
  // went to the page, where Backspace then deleted the body the cell's row had selected (audit).
  const view = useRef<HTMLButtonElement>(null);
  const refocus = useRef(false);
  useEffect(() => {
    if (edit !== null || !refocus.current) return;
    view.current?.focus();
  }, [edit]);
  const close = (byKey = false) => {
    refocus.current = byKey;
    setEdit(null);
    setError(null);
  };
  const focused = () => {
    if (refocus.current) refocus.current = false;
    else open();
  };
  // A refused draft stays open for correction, at the time it was refused: once the time moves (the
  // ±1 s buttons, the slider) the row shows another time, and a retry applied there (review: r = 0.35
  // saved at t = 3 for a refusal at t = 1, without a word). It closed, dropping the text typed; it
  // now stays, the refusal replaced by a note saying where Enter applies it (timeMovedNote), and
  // the refusal comes back if the time returns to where it was refused. A cell whose commit does not
  // depend on the time (atCurrentTime false) keeps its refusal: the note would be wrong there.
  const refused = edit !== null && error !== null && atCurrentTime;
  /** The refusal shown and the time it was given at (set with it). */
  const refusal = useRef<{ text: string; at: number } | null>(null);
  useEffect(() => {
    if (!refused || !editor) return;
    return editor.ui.subscribe((s, p) => {
      const r = refusal.current;
      if (s.t === p.t || r === null) return;
      setError(s.t === r.at ? r.text : timeMovedNote(label, r.at, s.t));
    });
  }, [refused, editor, label]);

  const typed = edit?.typed ?? null;
  const draft = typed !== null && typed !== value ? typed : null;
  useOpenDraft(editor, label, committing ? null : draft, owner);

  // In a table the note is drawn over the rows beside the field, never in its row (useCellNote).
  const field = useRef<HTMLInputElement>(null);
  const note = useRef<HTMLSpanElement>(null);
  const noted = edit !== null && (waiting || error !== null);
  useCellNote(field, note, noted);

  // A refusal that lapses (an edit at a time the history has not reached yet, behindRefusals.ts) is
  // dropped once the history gets there, or replaced by the one that holds then; the draft stays for
  // Enter. It stayed until Enter, long after the computation had passed the time.
  const shownError = useRef<string | null>(null);
  shownError.current = error;
  const followRefusal = (err: string) => {
    void editor?.refusalChanged(err)?.then((next) => {
      if (shownError.current !== err) return; // corrected, closed or refused again meanwhile
      shownError.current = next;
      const at = refusal.current?.at ?? 0;
      refusal.current = next === null ? null : { text: next, at };
      setError(next);
      if (next !== null) followRefusal(next);
    });
  };

  const commit = async (byKey = false) => {
    if (pending.current) return;
    if (typed === null || typed === value) {
      close(byKey);
      return;
    }
    pending.current = true;
    setCommitting(true);
    // An edit in the past is answered once the actions after it are checked (seconds in a large
    // scene): past SLOW_COMMIT_MS the cell says so.
    const slow = setTimeout(() => setWaiting(true), SLOW_COMMIT_MS);
    try {
      const err = await onCommit(typed.trim());
      if (err === null || err === UNDONE_DURING_CHECK) close(byKey);
      else {
        refusal.current = { text: err, at: editor?.ui.getState().t ?? 0 };
        setError(err);
        followRefusal(err);
      }
    } finally {
      clearTimeout(slow);
      setWaiting(false);
      pending.current = false;
      setCommitting(false);
    }
  };

  if (edit === null)
    return (
      <button
        type="button"
        className="cell-view"
        aria-label={label}
        onClick={open}
        onFocus={focused}
        ref={view}
      >
        {value}
      </button>
    );

  return (
    <span className="cell">
      <input
        ref={field}
        aria-label={label}
        // a draft typed and not committed: Save file says it is not in the file (sceneFile.ts)
        data-draft={draft !== null ? "" : undefined}
        aria-invalid={error !== null}
        aria-describedby={error ? errorId : undefined}
        size={size}
        // biome-ignore lint/a11y/noAutofocus: the input replaces the focused cell button
        autoFocus
        value={typed ?? value}
        // opened, the value is selected, so typing replaces it (audit of session 20: tabbed into,
        // the caret sat at the end and typing "-300" after "-100" was refused); a draft kept for
        // correction is not
        onFocus={(e) => {
          if (typed === null) e.currentTarget.select();
        }}
        onChange={(e) => setEdit({ typed: e.target.value })}
        onBlur={() => {
          if (error === null) void commit();
        }}
        onKeyDown={(e) => {
          // a held row scrolled out of view keeps its field's focus: what is typed is shown first
          if (revealsField(e.key)) revealField(e.currentTarget);
          if (e.key === "Enter") {
            // Closed during this keydown, the cell focuses its button, and the same Enter's keypress
            // would click it open again (an unchanged value never closed): the key ends here.
            e.preventDefault();
            void commit(true);
          }
          if (e.key === "Escape") close(true);
        }}
      />
      {noted && (
        <span className="cell-note" ref={note}>
          {waiting && (
            <span role="status" className="cell-waiting">
              checking the later actions…
            </span>
          )}
          {error && (
            <span id={errorId} role={inBar ? undefined : "alert"} className="cell-error">
              {error}
            </span>
          )}
        </span>
      )}
    </span>
  );
}

/**
 * What a refused draft says once the time has moved from `at`, where it was refused, to `now`: the
 * row shows another time, and Enter would apply the draft there.
 */
export function timeMovedNote(label: string, at: number, now: number): string {
  return `${label}: refused at t = ${formatNumber(at)} s; the time is now ${formatNumber(now)} s, where Enter applies it (Escape drops it)`;
}

/** Parses a number typed in a cell ("Infinity" and "∞" allowed); null when it is not a number. */
export function parseNumber(text: string): number | null {
  const t = text.trim();
  if (isInfinityWord(t)) return Number.POSITIVE_INFINITY;
  if (t === "" || !/^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(t)) return null;
  return Number(t);
}

/** Whether `text` names infinity (∞, Infinity, inf), rather than a number too large for a double. */
export function isInfinityWord(text: string): boolean {
  const t = text.trim();
  return t === "∞" || t === "Infinity" || t === "inf";
}

/** From this magnitude on numbers are written with an exponent (they stay narrow in a table). */
const EXPONENT_FROM = 1e7;

/**
 * A short display of a number: 6 significant digits, no trailing zeros, ∞ for infinities, an
 * exponent from 10^7 on ("1e+12", "1.23457e+9"); parseNumber reads every form back.
 */
export function formatNumber(x: number): string {
  if (x === Number.POSITIVE_INFINITY) return "∞";
  if (x === Number.NEGATIVE_INFINITY) return "-∞";
  if (Object.is(x, -0) || Math.abs(x) < 1e-12) return "0";
  const rounded = Number(x.toPrecision(6));
  if (Math.abs(rounded) < EXPONENT_FROM) return String(rounded);
  return rounded.toExponential();
}
