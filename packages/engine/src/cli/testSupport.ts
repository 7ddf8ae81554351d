/**
 * Helpers of the CLI's in-process tests (not built, not published): a CliIO over in-memory files that
 * records stdout and stderr, scene texts, and an interrupt control that interrupts after a number of
 * pauses.
 */
import type { CliIO } from "./io.js";
import type { InterruptSignal } from "./slices.js";

/** A CliIO reading `files` (a missing one fails as Node's read does), recording what is written. */
export function io(files: Record<string, string>, progress = false) {
  const out = { stdout: "", stderr: "" };
  const cli: CliIO = {
    readFile: (p) => {
      const f = files[p];
      if (f === undefined)
        throw Object.assign(new Error(`ENOENT: no such file or directory, open '${p}'`), { code: "ENOENT" });
      return f;
    },
    stdout: (t) => {
      out.stdout += t;
    },
    stderr: (t) => {
      out.stderr += t;
    },
    progress,
  };
  return { cli, out };
}

/** A version-1 scene file's text: these actions, no friction field, the given gravity. */
export function sceneText(actions: unknown[], gravity: [number, number] = [0, 0]): string {
  return JSON.stringify({ format: "chapgame", version: 1, g: 0, gravity, actions });
}

/** A disc bounces between two walls; at t = 5 gravity comes on under a disc resting on a floor. */
export const RESTS_AT_5 = [
  { time: 0, type: "addLine", id: "left", p1: [-10, -5], p2: [-10, 5], kind: "line" },
  { time: 0, type: "addLine", id: "right", p1: [10, -5], p2: [10, 5], kind: "line" },
  { time: 0, type: "addLine", id: "floor", p1: [-50, -100], p2: [-30, -100], kind: "segment" },
  { time: 0, type: "addBody", id: "ball", x: 0, y: 0, r: 1, m: 1, v: [9, 0] },
  { time: 0, type: "addBody", id: "rest", x: -40, y: -99, r: 1, m: 1 },
  { time: 5, type: "setGlobal", gravity: [0, -1] },
];

/** Pauses at once; reports `signal` once, at the `after`-th pause. */
export function interruptAfter(after: number, signal: InterruptSignal) {
  return interruptsAt(signal, after);
}

/** Pauses at once; reports `signal` once at each of the `at`-th pauses (as the bin reports each
 *  signal it receives once). */
export function interruptsAt(signal: InterruptSignal, ...at: number[]) {
  let pauses = 0;
  return {
    pause: async () => {
      pauses++;
    },
    interrupted: () => (at.includes(pauses) ? signal : null),
  };
}
