/**
 * SceneError: invalid scene or action input. `path` names the offending field (`actions[3].r`),
 * `reason` says what is wrong, and the message is `${path}: ${reason}` (one line, for users).
 */
export class SceneError extends Error {
  readonly path: string;
  readonly reason: string;
  constructor(path: string, reason: string) {
    super(path === "" ? reason : `${path}: ${reason}`);
    this.name = "SceneError";
    this.path = path;
    this.reason = reason;
  }
}
