/**
 * A field whose typed text is applied on Enter or on leaving it: the Time, Speed, Seconds ahead,
 * Events ahead and window width fields. Until the user types, the field shows `shown` (the live
 * value); clicking in and out applies nothing. Typed text is given, trimmed, to `apply`, which
 * applies it and returns null, or returns the refusal (naming the field: typedRefusal.ts) and
 * changes nothing. A refusal is shown beside the field (it describes the input, which is marked
 * invalid) and in the message bar, and the text typed stays in the field for correction: it was
 * replaced by the old value, the user's text lost (session 26). Leaving the field with the refused
 * text unchanged does not refuse it again; Escape drops the text and the refusal (in the message bar
 * too). The refusal beside
 * the field is an alert only when the message bar does not show the same text (a screen reader
 * announced each twice), as a table cell's (EditableCell). An applied value takes the refusal down
 * once a pointer pressed meanwhile is released (pointerRelease.ts: the button pressed moved away).
 */
import { type ReactNode, useId, useState } from "react";
import { useEditor, useUi } from "../EditorContext";
import { afterPointerRelease } from "./pointerRelease";

export interface TypedField {
  /** What the field shows: the text typed, else `shown`. */
  text: string;
  /** The input's props (spread them on it, with its own aria-label and size). */
  input: {
    value: string;
    "aria-invalid": boolean;
    "aria-describedby": string | undefined;
    onChange: (e: React.ChangeEvent<HTMLInputElement>) => void;
    onBlur: () => void;
    onKeyDown: (e: React.KeyboardEvent<HTMLInputElement>) => void;
  };
  /** The refusal to render beside the field (null when none). */
  refusal: ReactNode;
}

export function useTypedField(shown: string, apply: (typed: string) => string | null): TypedField {
  const editor = useEditor();
  /** The text typed (null: nothing typed; the field shows `shown`). */
  const [draft, setDraft] = useState<string | null>(null);
  /** The refusal of `refused`, the text last refused (both null when none). */
  const [refusal, setRefusal] = useState<{ text: string; refused: string } | null>(null);
  const errorId = useId();
  const inBar = useUi((s) => refusal !== null && s.message?.text === refusal.text);

  const commit = () => {
    if (draft === null || draft === refusal?.refused) return;
    const why = apply(draft.trim());
    if (why === null) {
      setDraft(null);
      // not under a pointer pressing a button below it (pointerRelease.ts)
      if (refusal !== null) afterPointerRelease(() => setRefusal((r) => (r === refusal ? null : r)));
      return;
    }
    setRefusal({ text: why, refused: draft });
    editor.ui.setState({ message: { text: why, tone: "error" } });
  };
  const drop = () => {
    // the refusal goes from the message bar too (it no longer describes anything typed)
    if (refusal !== null && editor.ui.getState().message?.text === refusal.text)
      editor.ui.setState({ message: null });
    setDraft(null);
    setRefusal(null);
  };

  const text = draft ?? shown;
  return {
    text,
    input: {
      value: text,
      "aria-invalid": refusal !== null,
      "aria-describedby": refusal === null ? undefined : errorId,
      onChange: (e) => setDraft(e.target.value),
      onBlur: commit,
      onKeyDown: (e) => {
        if (e.key === "Enter") commit();
        else if (e.key === "Escape") drop();
      },
    },
    refusal:
      refusal === null ? null : (
        <span id={errorId} role={inBar ? undefined : "alert"} className="field-error">
          {refusal.text}
        </span>
      ),
  };
}
