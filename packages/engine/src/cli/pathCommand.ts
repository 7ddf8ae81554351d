/**
 * `path`: body --id's pieces over [--from, --to] (Timeline.path). firstAdded refuses an id no addBody
 * of the scene names (a UsageError about the scene, shown after the file's name, before anything is
 * computed); pathResult gives the pieces, or after an error or an interrupt the pieces up to where
 * the run stopped, with why.
 */
import type { SceneFile } from "../scene/types.js";
import type { PathPiece } from "../timeline/path.js";
import type { Timeline } from "../timeline/timeline.js";
import { type Command, UsageError } from "./args.js";
import type { PathResult, RunEnd } from "./output.js";

/**
 * The time of the first addBody of `id` in the scene; refuses a `path --id` that no addBody action
 * names (a typo would else print nothing).
 */
export function firstAdded(scene: SceneFile, id: string): number {
  const ids = new Set<string>();
  let first = Infinity;
  for (const a of scene.actions) {
    if (a.type !== "addBody") continue;
    ids.add(a.id);
    if (a.id === id && a.time < first) first = a.time;
  }
  if (ids.has(id)) return first;
  const known = [...ids].sort();
  const list =
    known.length <= 10 ? known.join(", ") : `${known.slice(0, 10).join(", ")}, … (${known.length} in all)`;
  throw new UsageError(
    `--id: no body ${JSON.stringify(id)} in the scene (${known.length === 0 ? "it adds no body" : `bodies: ${list}`})`,
    true, // after the file's name, as the other errors about its contents
  );
}

export type PathCommand = Extract<Command, { command: "path" }>;

/**
 * The body's pieces over [from, to]: none when the body is first added (at `added`) after `to`, or
 * exactly at `to` without the addition having taken place there (Timeline.path refuses an id the
 * history has not met yet; for the command, a body that does not exist yet has no piece). A span
 * of no length gives Timeline.path's one point (a piece with until = from) when the body exists.
 */
function piecesUpTo(tl: Timeline, cmd: PathCommand, added: number, to: number): PathPiece[] {
  const exists = added < to || (added === to && tl.stateAt(to).bodies.some((b) => b.id === cmd.id));
  return to >= cmd.from && exists ? tl.path(cmd.id, cmd.from, to) : [];
}

/**
 * The pieces of the path command's body over [from, to], or, after a run that stopped early (`end`),
 * up to where it stopped: none when that is before `from` or before the body was first added (at
 * `added`; added exactly where the run stopped, it counts when the addition took place).
 */
export function pathResult(tl: Timeline, cmd: PathCommand, added: number, end?: RunEnd): PathResult {
  if (end === undefined)
    return { id: cmd.id, from: cmd.from, to: cmd.to, pieces: piecesUpTo(tl, cmd, added, cmd.to) };
  const to = tl.horizon;
  const early =
    end.reason === "error"
      ? { reason: "error" as const, error: end.error }
      : { reason: "interrupted" as const };
  return { id: cmd.id, from: cmd.from, to, end: early, pieces: piecesUpTo(tl, cmd, added, to) };
}
