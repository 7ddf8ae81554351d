/**
 * The file name the current scene came from (an opened file's, a preset's, the name it was last
 * saved under; null when none: a cleared, pasted or linked scene), which Save file suggests
 * (doc/saveName.ts). A load starts a new file, named by the load; edits stay in the file they were
 * made in; saving under a name renames the file, the versions of it in the undo history included.
 * It follows the undo history: every scene that leaves the current place (an edit, a load, an Undo
 * or Redo away from it) is tagged with its file, and a scene Undo or Redo brings back is in its
 * file again, so that undoing the opening of billiards.chapgame.json suggests the name of the scene
 * before it, and redoing it billiards.chapgame.json again. A preset's name is the editor's, not the
 * author's (`preset`): a title the author gives the scene then names the file (Editor.setTitle).
 */
import type { SceneFile } from "./engineTypes";
import { createStore, type Store } from "./store/createStore";

/** One file: the scenes of one load and the edits after it share it. */
interface NamedFile {
  name: string | null;
  /** The name is a preset's (the editor gave it), not one the author chose or opened. */
  preset: boolean;
}

export class SceneNames {
  /** The current scene's file name (null: none). */
  readonly current: Store<{ name: string | null }> = createStore<{ name: string | null }>({ name: null });
  private file: NamedFile = { name: null, preset: false };
  /** The file of each scene that left the current place (history entries hold these scenes). */
  private readonly files = new WeakMap<SceneFile, NamedFile>();

  get name(): string | null {
    return this.file.name;
  }

  /** Whether the current file's name is a preset's (or none): one the author did not choose. */
  get chosen(): boolean {
    return this.file.name !== null && !this.file.preset;
  }

  /** A load: the current scene starts a new file named `name` (null: none), a preset's when `preset`. */
  loaded(name: string | null, preset = false): void {
    this.file = { name, preset };
    this.current.setState({ name });
  }

  /** Saved under `name`: the current file is renamed, also where the undo history holds it. */
  saved(name: string): void {
    this.file.name = name;
    this.file.preset = false;
    this.current.setState({ name });
  }

  /** `scene`, the current one, leaves the current place: it stays in its file for its return. */
  left(scene: SceneFile): void {
    this.files.set(scene, this.file);
  }

  /**
   * `scene` comes back (Undo or Redo) after `from` left: it is in its file again. A scene never
   * tagged (an edit an Undo took back during its check, then redone) stays in the current file.
   */
  returned(from: SceneFile, scene: SceneFile): void {
    this.left(from);
    const file = this.files.get(scene);
    if (file === undefined) return;
    this.file = file;
    this.current.setState({ name: file.name });
  }
}
