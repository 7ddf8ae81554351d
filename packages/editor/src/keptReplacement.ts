/**
 * The scene a load replaced, kept beside this tab's autosave slot (autosave.ts): a load that
 * replaces the scene (Clear, a preset, an opened scene: Editor.replaced) keeps the scene it took
 * away (doc/autosaveSlots.ts keepsReplaced, written with the next save), so the autosave of the new
 * scene 300 ms later no longer makes the old one unreachable: a reload loads it as the step Undo goes
 * back to (boot.ts firstScene). While Undo has undone that load, the kept scene is that of the latest
 * earlier load not undone, or none (Redo brings it back): a reload never offers a scene as replaced
 * when nothing replaced it in the end. This module decides which scene that is; autosave.ts writes it.
 */
import { keepsReplaced } from "./doc/autosaveSlots";
import { sceneText } from "./doc/sceneIo";
import type { Replacement } from "./replacementSteps";

/** Recent loads whose replaced scene a tab remembers (the latest not undone is kept). */
const KEPT_MAX = 8;

export class KeptReplacement {
  /** The scene text the last replacing load loaded when it was a preset or Clear's (keepsReplaced). */
  private reproducibleText: string | null = null;
  /** The recent loads whose replaced scene is to be kept (keepsReplaced), with that scene's text. */
  private kept: { by: Replacement; text: string }[] = [];
  /** The recent replacements whose undo step is undone now (EditorSession.replaced). */
  private undone: ReadonlySet<Replacement> = new Set();
  /**
   * The scene to keep beside the slot: the one the latest kept load whose step is not undone took
   * away (Undo after a reload goes back to it as Undo now would), or null.
   */
  text: string | null = null;
  /** Whether `text` is still to be written (or, null, the kept scene removed). */
  pending = false;

  /**
   * A load replaced `before` with `loaded` (Editor.replaced): `before` is kept beside the slot with
   * the next save, unless there is nothing in it to lose (keepsReplaced: empty, or a preset's or
   * Clear's scene unedited).
   */
  replacedBy(replacement: Replacement): void {
    const { before, loaded, reproducible } = replacement;
    const text = sceneText(before);
    if (keepsReplaced({ text, empty: before.actions.length === 0 }, this.reproducibleText))
      this.kept = [...this.kept, { by: replacement, text }].slice(-KEPT_MAX);
    this.reproducibleText = reproducible ? sceneText(loaded) : null;
    this.keepLatest();
  }

  /**
   * The replacements whose step Undo undid (`undone`, EditorSession.replaced): the scene one of them
   * took away is kept no longer (a reload would offer it as replaced though nothing replaced it),
   * and is kept again once Redo brings its step back.
   */
  undoneNow(undone: ReadonlySet<Replacement>): void {
    this.undone = undone;
    this.keepLatest();
  }

  private keepLatest(): void {
    const text = [...this.kept].reverse().find((k) => !this.undone.has(k.by))?.text ?? null;
    if (text === this.text) return;
    this.text = text;
    this.pending = true;
  }
}
