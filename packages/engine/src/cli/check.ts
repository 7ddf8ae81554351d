/**
 * `check`: a scene validated whole (checkScene): its fields (parseScene), then every action against
 * the simulation, computed exactly up to the last action (a headless Timeline), which ends for any
 * scene; it prints {"valid": …} either way (see checkScene).
 */
import { parseSceneFrom, printable } from "../scene/parse.js";
import { ChapgameError, SimulationError } from "../sim/errors.js";
import { Timeline } from "../timeline/timeline.js";
import type { ProgressLine } from "./progress.js";
import { Interrupted } from "./slices.js";

/**
 * `check`: the scene's fields (parseScene of the text `read` gives; a UsageError when it cannot be
 * read), then every action applied to the simulation computed up
 * to the last action's time (a headless Timeline: no log kept), which ends for any scene. Prints
 * {"valid": true, "actions", "checkedTo", "events"} and returns 0, or {"valid": false, "error",
 * "path"} (the message on stderr too, after the file's name) and returns 2; a Zeno state before the
 * last action is invalid too (path null). An interrupt prints nothing on stdout and returns 130 / 143.
 * `compact` writes the object on one line (`--compact`), else indented.
 */
export function* checkScene(
  read: () => string,
  file: string,
  line: ProgressLine,
  compact = false,
): Generator<void, number, void> {
  const io = line.io;
  const write = (result: object) => io.stdout(`${JSON.stringify(result, null, compact ? 0 : 2)}\n`);
  const invalid = (e: Error, path: string | null) => {
    const error = printable(e.message);
    write({ valid: false, error, path });
    io.stderr(
      `chapgame: ${file}: ${e instanceof SimulationError ? "cannot simulate this scene: " : ""}${error}\n`,
    );
    return 2;
  };
  let tl: Timeline;
  let last = 0;
  let count = 0;
  try {
    const scene = parseSceneFrom(read);
    for (const a of scene.actions) if (a.time > last) last = a.time;
    count = scene.actions.length;
    line.building(scene);
    tl = Timeline.fromParsedScene(scene, { history: false, compute: false });
  } catch (e) {
    if (e instanceof ChapgameError) return invalid(e, e.path);
    if (e instanceof SimulationError) return invalid(e, null);
    throw e;
  }
  io.computing?.();
  try {
    yield* line.compute(tl, { time: last });
  } catch (e) {
    io.computed?.();
    if (e instanceof Interrupted) {
      io.stderr(
        `chapgame: ${file}: interrupted by ${e.signal} at t = ${tl.horizon}: the check did not finish\n`,
      );
      return e.status;
    }
    if (e instanceof ChapgameError) return invalid(e, e.path);
    if (e instanceof SimulationError) return invalid(e, null);
    throw e;
  }
  io.computed?.();
  const c = tl.counts();
  write({
    valid: true,
    actions: count,
    checkedTo: last,
    events: c.bodyBody + c.bodyLine + c.bodyPoint + c.stop,
  });
  return 0;
}
