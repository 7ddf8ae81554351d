/**
 * The drafts typed in the editor's cells and not applied, so that an edit that takes a draft away
 * with its object says so: a delete, a rename, a removed add, or a load that replaces the scene
 * unmounted the cell and the text typed vanished without a word. Contract: a cell records its draft
 * (`set(key, draft)`, a key of its own) while the text typed differs from the value it shows, and
 * clears it (`set(key, null)`) once committed, closed or unmounted (panels/useOpenDraft.ts). The
 * edits read `of(owner)` or `all()` before the cells unmount (the rows go with the next frame of the
 * table) and add `droppedNote` of what they read to the message they give. A draft's owner is the
 * object and field of a table's cell; the Globals and the refused action's cells have none (only a
 * load takes them away). Pure bookkeeping: no React, no DOM.
 */
import type { ObjectKind } from "./doc/rename";
import { typedGiven } from "./panels/typedRefusal";

/** The object and field a table cell edits. */
export interface DraftOwner {
  kind: ObjectKind;
  id: string;
  /** The column: "id" for the rename cell, "x", "r", "p1 x", … */
  field: string;
}

/** A draft as a message names it: the cell's label and the text typed. */
export interface OpenDraft {
  label: string;
  text: string;
  owner: DraftOwner | null;
}

export class OpenDrafts {
  private readonly drafts = new Map<string, OpenDraft>();

  /** Records the draft of the cell `key`, or clears it (null). */
  set(key: string, draft: OpenDraft | null): void {
    if (draft === null) this.drafts.delete(key);
    else this.drafts.set(key, draft);
  }

  /** Every draft, in the order the cells recorded them. */
  all(): OpenDraft[] {
    return [...this.drafts.values()];
  }

  /** The drafts of the object `kind` `id`, but those of the field `except` (the rename's own cell). */
  of(kind: ObjectKind, id: string, except?: string): OpenDraft[] {
    return this.all().filter(
      (d) => d.owner !== null && d.owner.kind === kind && d.owner.id === id && d.owner.field !== except,
    );
  }
}

/** Longest list of drafts named one by one; the rest are counted. */
const NAMED_MAX = 3;

/**
 * The sentence saying that `drafts` were dropped ("Dropped the draft b3 r = -1, typed and not
 * applied."), or "" when there are none. What was typed is written as the refusals write it: a
 * number as typed, other text quoted (panels/typedRefusal.ts).
 */
export function droppedNote(drafts: readonly OpenDraft[]): string {
  if (drafts.length === 0) return "";
  const named = drafts.slice(0, NAMED_MAX).map((d) => `${d.label} = ${typedGiven(d.text)}`);
  const more = drafts.length - named.length;
  if (more > 0) named.push(`${more} more`);
  const list = named.length === 1 ? named[0] : `${named.slice(0, -1).join(", ")} and ${named.at(-1)}`;
  return `Dropped the draft${drafts.length === 1 ? "" : "s"} ${list}, typed and not applied.`;
}
