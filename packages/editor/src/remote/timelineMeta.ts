/**
 * The meta of each timeline the worker holds, set since it was made (op `meta`): the engine's
 * Timeline keeps only the meta of the scene it was made from, and setting a meta recomputes nothing.
 * Kept per timeline (weakly), so a timeline given back (a change taken back, hostCompute.ts) has its
 * own meta again. Metas are stored and given out as deep copies (JSON), never shared with a caller.
 */
import type { SceneFile } from "../engineTypes";
import type { TimelineLike } from "./timelineLike";

export class TimelineMetas {
  /** The meta set on a timeline since it was made (null: none, as a removed meta). */
  private readonly metas = new WeakMap<TimelineLike, Record<string, unknown> | null>();

  /** The scene of `tl`: its own (Timeline.toScene), with the meta set on it since, if any. */
  sceneOf(tl: TimelineLike): SceneFile {
    const scene = tl.toScene();
    if (!this.metas.has(tl)) return scene;
    const meta = this.metas.get(tl) ?? null;
    if (meta === null) delete scene.meta;
    else scene.meta = JSON.parse(JSON.stringify(meta)) as Record<string, unknown>;
    return scene;
  }

  /** Sets `tl`'s meta (a copy; null removes it from the scene). */
  set(tl: TimelineLike, meta: Record<string, unknown> | null): void {
    this.metas.set(tl, meta === null ? null : (JSON.parse(JSON.stringify(meta)) as Record<string, unknown>));
  }
}
