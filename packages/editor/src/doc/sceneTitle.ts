/**
 * The scene's title, `meta.title` (scene-format.md: `meta` is free data for tools, kept as it is),
 * as the header's Title field edits it. Pure.
 * - titleOf: the title shown: `meta.title` when a string, else "" (a title of another type, which
 *   only a file written elsewhere holds, is not text to show; typing a title replaces it).
 * - metaWithTitle: the meta once `typed` is the title: the text without its outer white space; a
 *   blank one removes `meta.title` (and `meta` once nothing else is in it). The format limits the
 *   strings of `meta` in nothing (any JSON string round-trips), so no title is refused. The rest of
 *   `meta` is kept as it is.
 * - titleChange: what a change of the title is called in Undo's and Redo's messages, null when
 *   the titles are the same.
 * - differsInMetaAlone: whether two scenes differ in their meta and in nothing else (a title
 *   changed, or its undo), so that nothing needs recomputing between them. Scenes with the same
 *   meta are answered without writing them out (every Undo and Redo asks).
 */
import type { SceneFile } from "../engineTypes";
import { sceneText } from "./sceneIo";

type Meta = Record<string, unknown>;

/** The title shown in the Title field: `meta.title` when a string, else "". */
export function titleOf(doc: SceneFile): string {
  const v = doc.meta?.title;
  return typeof v === "string" ? v : "";
}

/** The scene's meta with `typed` as its title (undefined: no meta at all). */
export function metaWithTitle(meta: Meta | undefined, typed: string): Meta | undefined {
  const title = typed.trim();
  const next: Meta = { ...meta };
  if (title === "") delete next.title;
  else next.title = title;
  return Object.keys(next).length === 0 ? undefined : next;
}

/** "the title set to "B"", "the title "A" removed", "the title changed from "A" to "B"", or null. */
export function titleChange(before: SceneFile, after: SceneFile): string | null {
  const a = titleOf(before);
  const b = titleOf(after);
  if (a === b && before.meta?.title === after.meta?.title) return null;
  if (a === "" && b !== "") return `the title set to ${JSON.stringify(b)}`;
  if (b === "") return a === "" ? "a change of the title" : `the title ${JSON.stringify(a)} removed`;
  return `the title changed from ${JSON.stringify(a)} to ${JSON.stringify(b)}`;
}

/** Whether `a` and `b` differ in their meta, and only there. */
export function differsInMetaAlone(a: SceneFile, b: SceneFile): boolean {
  if (a.actions.length !== b.actions.length || JSON.stringify(a.meta) === JSON.stringify(b.meta))
    return false;
  return sceneText({ ...a, meta: undefined }) === sceneText({ ...b, meta: undefined });
}
