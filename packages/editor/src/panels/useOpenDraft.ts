/**
 * Records a cell's draft in the editor's OpenDrafts (openDrafts.ts) while there is one: `text` is
 * the text typed when it differs from the value shown, else null. Cleared when the cell closes,
 * commits or unmounts; outside an editor (a cell rendered alone) nothing is recorded.
 */
import { useEffect, useId } from "react";
import type { Editor } from "../editor";
import type { DraftOwner } from "../openDrafts";

export function useOpenDraft(
  editor: Editor | null,
  label: string,
  text: string | null,
  owner: DraftOwner | undefined,
): void {
  const key = useId();
  const kind = owner?.kind;
  const id = owner?.id;
  const field = owner?.field;
  useEffect(() => {
    if (!editor || text === null) return;
    const drafts = editor.drafts;
    drafts.set(key, {
      label,
      text,
      owner: kind === undefined || id === undefined || field === undefined ? null : { kind, id, field },
    });
    return () => drafts.set(key, null);
  }, [editor, key, label, text, kind, id, field]);
}
