/**
 * The undo steps of loads that replaced the scene (Clear, a preset, an opened file or link; not a
 * rewrite of the current scene), for EditorSession (editorSession.ts). Published in a store
 * (`replaced`: the last such load, and the recent ones whose step is undone now), so that the
 * autosave keeps the scene taken away while, and only while, that load is done (keptReplacement.ts);
 * and read by Undo and Redo (editorUndo.ts), which name such a step as a load, not as an edit.
 */
import { HISTORY_LIMIT, type History } from "./doc/history";
import type { SceneFile } from "./engineTypes";
import { createStore, type Store } from "./store/createStore";

/**
 * A load that replaced the scene `before` with `loaded`; `reproducible`: `loaded` can be had again as
 * it was (a preset, Clear's empty scene), so replacing it unedited loses nothing.
 */
export interface Replacement {
  before: SceneFile;
  loaded: SceneFile;
  reproducible: boolean;
}

/** EditorSession.replaced. */
export interface Replaced {
  last: Replacement | null;
  /** Replacements whose undo step is undone now (the scene they took away is the scene, or after it). */
  undone: ReadonlySet<Replacement>;
}

export class ReplacementSteps {
  /**
   * The last load that replaced the scene (the scene it took away and the one it loaded), and the
   * recent ones whose undo step is undone now (Undo went back past them; Redo may bring them back).
   */
  readonly replaced: Store<Replaced> = createStore<Replaced>({ last: null, undone: new Set() });
  /** Each recent replacement's undo step: its entry in Undo while done, the scene in Redo after it while undone. */
  private steps: { replacement: Replacement; entry: SceneFile; done: boolean }[] = [];

  /** A load replaced `replacement.before` (the entry its undo step records) and is published. */
  recorded(replacement: Replacement): void {
    this.steps = [...this.steps, { replacement, entry: replacement.before, done: true }].slice(
      -HISTORY_LIMIT,
    );
    this.replaced.setState({ last: replacement });
  }

  /**
   * After Undo (`undo`) or Redo restored `scene` with the history `h`: a replacement whose step that
   * was is undone (its scene after goes to Redo) or done again (its entry is the scene before).
   * Whether such a step was taken (the scene was replaced by another).
   */
  stepped(undo: boolean, scene: SceneFile, h: History): boolean {
    let changed = false;
    for (const step of this.steps)
      if (step.entry === scene && step.done === undo) {
        step.done = !undo;
        step.entry = (undo ? h.future[0] : h.past[h.past.length - 1]) ?? scene;
        changed = true;
      }
    if (changed)
      this.replaced.setState({
        undone: new Set(this.steps.filter((s) => !s.done).map((s) => s.replacement)),
      });
    return changed;
  }

  /**
   * What Undo (`undo` true) or Redo says when it goes to `scene`: a load that replaced the scene (a
   * preset, a file, a link, Clear) is named as one ("Undone: a change of 19 actions" read as an
   * edit: review), else null (the caller describes the edit).
   */
  summary(scene: SceneFile, undo: boolean): string | null {
    const step = this.steps.find((s) => s.entry === scene && s.done === undo);
    if (!step) return null;
    const n = scene.actions.length;
    const actions = `${n} action${n === 1 ? "" : "s"}`;
    return undo
      ? `Undone: the scene loaded over yours; back to your scene (${actions}).`
      : `Redone: the scene loaded (${actions}).`;
  }
}
