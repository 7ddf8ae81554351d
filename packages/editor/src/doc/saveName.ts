/**
 * The file name Save file suggests for a scene (pure). In order: the name the scene came from (the
 * file it was opened from, the name it was last saved under, a preset's), then a name made from the
 * scene's own title (`meta.title`, else `meta.name`, when a non-blank string), then DEFAULT_SAVE_NAME.
 * A name made from a title keeps its letters and digits (any script), joins the rest with hyphens,
 * and ends in SCENE_SUFFIX; a name the scene came from is kept as it was.
 */
import type { SceneFile } from "../engineTypes";

/** What every name made here ends with. */
export const SCENE_SUFFIX = ".chapgame.json";

/** The name when the scene came from no file and has no title. */
export const DEFAULT_SAVE_NAME = `scene${SCENE_SUFFIX}`;

/** Longest stem made from a title (file systems allow 255 bytes; a title may be a paragraph). */
const MAX_STEM = 80;

/** The file name for a scene whose source file is `source` (null: none). */
export function saveNameFor(source: string | null, doc: SceneFile): string {
  if (source !== null && source.trim() !== "") return source;
  const title = sceneTitle(doc);
  return title === null ? DEFAULT_SAVE_NAME : fileNameFrom(title);
}

/** The scene's title: `meta.title`, else `meta.name`, when a string with a letter or digit. */
export function sceneTitle(doc: SceneFile): string | null {
  for (const key of ["title", "name"]) {
    const v = doc.meta?.[key];
    if (typeof v === "string" && /[\p{L}\p{N}]/u.test(v)) return v;
  }
  return null;
}

/**
 * "My Billiards!" → "my-billiards.chapgame.json"; "billiardsBreak" → "billiards-break.chapgame.json";
 * a text without letters or digits gives DEFAULT_SAVE_NAME.
 */
export function fileNameFrom(text: string): string {
  const stem = text
    .replace(/(\p{Ll})(\p{Lu})/gu, "$1-$2")
    .toLowerCase()
    .split(/[^\p{L}\p{N}]+/u)
    .filter((w) => w !== "")
    .join("-")
    .slice(0, MAX_STEM)
    .replace(/-+$/, "");
  return stem === "" ? DEFAULT_SAVE_NAME : `${stem}${SCENE_SUFFIX}`;
}
