/**
 * SceneError: invalid scene or action input. `path` names the offending field (`actions[3].r`),
 * `reason` says what is wrong, and the message is `${path}: ${reason}` (one line, for users).
 * It is a ChapgameError, so one `instanceof ChapgameError` catches every refused edit, action,
 * option or scene, whether a World, a Timeline or parseScene refused it. (Reads given a bad time or
 * index, and realRoots's arguments, throw RangeError, as they did before this class existed.)
 */
import { ChapgameError } from "../sim/errors.js";

/**
 * Invalid scene or action input (parseScene, serializeScene, checkAction, every Timeline edit and
 * option): a ChapgameError, so `path` names the field (`actions[3].r`) and `reason` says what is
 * wrong; the message is `${path}: ${reason}`.
 */
export class SceneError extends ChapgameError {
  constructor(path: string, reason: string) {
    super(path, reason);
    if (path === "") this.message = reason;
    this.name = "SceneError";
  }
}
